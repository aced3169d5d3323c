"""Self-contained HTML report of a diagnosis (PNG figures embedded as base64)."""
from __future__ import annotations

import base64
import html
import io

import numpy as np

__all__ = ["figures", "write_html"]


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    import matplotlib.pyplot as plt
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode()


def figures(report) -> dict[str, str]:
    """Base64 PNGs: residual vs signals, loops before/after, ranked candidates."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    models = report._models
    vals = report._data["validation"]
    val = vals[0]
    base = models["base"]
    cause = report["verdict"]["cause"]
    best = models.get(cause) or (models.get(report["effects"][0]["name"])
                                 if report["effects"] else None)
    Pb = base.predict(val)
    r = val.F - Pb
    out = {}
    sig = [("velocity v [m/s]", val.v), ("acceleration a [m/s^2]", val.a),
           ("position x [m]", val.x), ("time t [s]", val.t)]
    if val.load is not None:
        sig.append(("load [N]", val.load))
    fig, axes = plt.subplots(1, len(sig), figsize=(3.6 * len(sig), 3.2), sharey=True)
    for ax, (lab, s) in zip(axes, sig):
        ax.plot(s, r, ".", ms=1.5, alpha=0.4)
        ax.set_xlabel(lab)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("held-out residual F_meas - F_model [N]")
    fig.suptitle(f"residual of the base {report['baseline']['model']} on held-out data")
    fig.tight_layout()
    out["residuals"] = _png(fig)

    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].plot(val.v, val.F, ".", ms=1.5, color="0.6", label="measured")
    ax[0].plot(val.v, Pb, ".", ms=1.5, label="base model")
    if best is not None:
        ax[0].plot(val.v, best.predict(val), ".", ms=1.5, label=f"with {best.effects[0].name}"
                   if best.effects else "best candidate")
    ax[0].set(xlabel="velocity [m/s]", ylabel="friction [N]", title="friction loops, held out")
    ax[0].legend(markerscale=6, fontsize=8)
    ax[0].grid(alpha=0.3)
    n = min(val.t.size, 3000)
    ax[1].plot(val.t[:n], val.F[:n], color="0.6", label="measured")
    ax[1].plot(val.t[:n], Pb[:n], label="base model")
    if best is not None:
        ax[1].plot(val.t[:n], best.predict(val)[:n], label="with the named effect")
    ax[1].set(xlabel="time [s]", ylabel="friction [N]", title="time trace, held out")
    ax[1].legend(fontsize=8)
    ax[1].grid(alpha=0.3)
    fig.tight_layout()
    out["loops"] = _png(fig)

    eff = report["effects"]
    fig, ax = plt.subplots(figsize=(7, 0.45 * max(len(eff), 2) + 1))
    names = [e["name"] for e in eff][::-1]
    gaps = [100 * e["gap_closed"] for e in eff][::-1]
    ax.barh(names, gaps, color=["C3" if n == cause else "C0" for n in names])
    ax.axvline(0, color="k", lw=0.8)
    ax.set_xlabel("held-out gap closed [%]")
    ax.set_title("candidate effects, ranked")
    fig.tight_layout()
    out["candidates"] = _png(fig)
    return out


def write_html(report, path) -> None:
    figs = figures(report)
    b, v = report["baseline"], report["verdict"]
    rows = "".join(
        f"<tr><td>{html.escape(e['name'])}</td><td>{e['validation_before']:.4g}</td>"
        f"<td>{e['validation_after']:.4g}</td><td>{100 * e['gap_closed']:.1f} %</td></tr>"
        for e in report["effects"])
    where = "".join(f"<tr><td>{html.escape(w['label'])}</td><td>{100 * w['share']:.1f} %</td>"
                    f"<td>{w['nrmse']:.3g}</td></tr>" for w in report["where"])
    img = lambda k: f'<img src="data:image/png;base64,{figs[k]}" style="max-width:100%">'
    doc = f"""<!doctype html><html><head><meta charset="utf-8">
<title>frictionlab diagnosis</title>
<style>body{{font-family:sans-serif;max-width:1200px;margin:2em auto}}
table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;padding:3px 8px}}</style></head>
<body><h1>Sim-to-real gap diagnosis</h1>
<p><b>Verdict: {html.escape(str(v['cause']))}</b> (held-out gap closed
{100 * v['gap_closed']:.1f} %). {html.escape(v.get('reason', ''))}</p>
<p>Base model <code>{html.escape(b['model'])}</code>: fit NRMSE {b['fit']:.4g}, held-out NRMSE
{b['validation']:.4g}, estimated noise floor {report['noise_floor']:.3g}.</p>
<h2>Where the gap lies</h2><table><tr><th>region</th><th>share of residual energy</th>
<th>local NRMSE</th></tr>{where}</table>{img('residuals')}
<h2>Which effect</h2><table><tr><th>effect</th><th>held-out before</th><th>after</th>
<th>gap closed</th></tr>{rows}</table>{img('candidates')}
<h2>Friction before and after</h2>{img('loops')}
</body></html>"""
    with open(path, "w") as fh:
        fh.write(doc)
