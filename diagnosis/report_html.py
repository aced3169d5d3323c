"""Self-contained HTML report of a diagnosis (PNG figures embedded as base64)."""
from __future__ import annotations

import base64
import html
import io

import numpy as np

__all__ = ["figures", "write_html", "candidates_png", "contract_tables", "img_tag", "PAGE_HEAD"]


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    import matplotlib.pyplot as plt
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode()


def _binned_median(s, r, bins: int = 25):
    """Median of the residual in equal-count bins of a signal: the structure a scatter of
    thousands of points hides."""
    s = np.asarray(s, float)
    order = np.argsort(s, kind="stable")
    chunks = [c for c in np.array_split(order, bins) if c.size]
    return (np.array([np.median(s[c]) for c in chunks]),
            np.array([np.median(r[c]) for c in chunks]))


def _table(header, rows) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def _effect_parameters(report, name) -> list[tuple[str, str, str]]:
    """(parameter, fitted value, unit) of a candidate's own parameters."""
    from .effects import CANDIDATES
    comp = report._models.get(name)
    if comp is None or name not in CANDIDATES:
        return []
    units = {e.name: e.unit for e in CANDIDATES[name].force_extras(comp.ctx)}
    rows = [(k, f"{v:.4g}", units.get(k, "")) for k, v in comp.extras.items()]
    base = set(report.get("base", {}).get("params", {}))
    law_units = {i.name: i.unit for i in comp.law.params.info()}
    for n in comp.base_names:  # parameters the candidate adds to the law itself
        if n not in base:
            rows.append((n, f"{float(getattr(comp.law.params, n)):.4g}", law_units.get(n, "")))
    return rows


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
        c, m = _binned_median(s, r)
        ax.plot(c, m, "-", color="C3", lw=1.5, label="binned median")
        ax.set_xlabel(lab)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
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

    out["candidates"] = candidates_png(report, "candidate effects, ranked")
    return out


def candidates_png(report, title: str) -> str:
    """Bar chart of the held-out gap each candidate closes, the named one in red (base64)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    eff = report["effects"]
    fig, ax = plt.subplots(figsize=(7, 0.45 * max(len(eff), 2) + 1))
    names = [e["name"] for e in eff][::-1]
    ax.barh(names, [100 * e["gap_closed"] for e in eff][::-1],
            color=["C3" if n == report["verdict"]["cause"] else "C0" for n in names])
    ax.axvline(0, color="k", lw=0.8)
    ax.set_xlabel("held-out gap closed [%]")
    ax.set_title(title)
    fig.tight_layout()
    return _png(fig)


#: head of every report page (both levels)
PAGE_HEAD = """<!doctype html><html><head><meta charset="utf-8">
<title>{title}</title>
<style>body{{font-family:sans-serif;max-width:1200px;margin:2em auto}}
table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;padding:3px 8px}}</style></head>"""


def contract_tables(report) -> tuple[str, str]:
    """HTML tables of the contract's ``where`` regions and ranked ``effects``."""
    where = _table(["region", "share of residual energy", "local NRMSE"],
                   [(html.escape(w["label"]), f"{100 * w['share']:.1f} %", f"{w['nrmse']:.3g}")
                    for w in report["where"]])
    effects = _table(["effect", "held-out before", "after", "gap closed",
                      "improvement z (paired, held-out)"],
                     [(html.escape(e["name"]), f"{e['validation_before']:.4g}",
                       f"{e['validation_after']:.4g}", f"{100 * e['gap_closed']:.1f} %",
                       f"{e['significance_z']:.1f}" if "significance_z" in e else "-")
                      for e in report["effects"]])
    return where, effects


def img_tag(png: str) -> str:
    return f'<img src="data:image/png;base64,{png}" style="max-width:100%">'


def write_html(report, path) -> None:
    figs = figures(report)
    b, v = report["baseline"], report["verdict"]
    where, rows = contract_tables(report)
    img = lambda k: img_tag(figs[k])
    esc = lambda x: html.escape(str(x))
    bands = _table(["band", "share of residual energy", "local NRMSE", "share of samples"],
                   [(esc(w["label"]), f"{100 * w['share']:.1f} %", f"{w['nrmse']:.3g}",
                     f"{100 * w.get('fraction_of_samples', float('nan')):.0f} %")
                    for w in report.get("where_bands", [])[:8]])
    freq = _table(["residual frequency band", "share of residual energy"],
                  [(esc(w["label"]), f"{100 * w['share']:.1f} %")
                   for w in report.get("where_frequency", [])])
    named = v["cause"] if v["cause"] in report._models else (
        report["effects"][0]["name"] if report["effects"] else None)
    params = _effect_parameters(report, named) if named else []
    params_html = (f"<h3>Fitted parameters of <code>{esc(named)}</code></h3>"
                   + _table(["parameter", "value", "unit"],
                            [(esc(a), b_, esc(c)) for a, b_, c in params])) if params else ""
    tr = report.get("transfer")
    which = ("<p>Each candidate is re-identified jointly with the base law on the fit data and "
             "scored on the held-out data.</p>")
    if tr:
        names = [e["name"] for e in report["effects"][:4]]
        which = (f"<p>Scored by transfer: {esc(tr['explanation'])}.</p>" + _table(
            ["calibrated on record", "scored on records", "base"] + [esc(n) for n in names],
            [(str(f["calibrated_on"]), ", ".join(map(str, f["scored_on"])), f"{f['before']:.4g}")
             + tuple(f"{f['after'][n]:.4g}" for n in names) for f in tr["folds"]]))
        fits = report.get("effect_details", {}).get(named, {}).get("transfer_params", [])
        if fits:
            keys = sorted({k for p in fits for k in p})
            params_html = (f"<h3>Parameters of <code>{esc(named)}</code> calibrated on each "
                           f"held-out record</h3>" + _table(
                               ["record"] + [esc(k) for k in keys],
                               [(str(i),) + tuple(f"{p.get(k, float('nan')):.4g}" for k in keys)
                                for i, p in enumerate(fits)]))
    g = report.get("greedy", {})
    seq = _table(["step", "effect added", "held-out NRMSE"],
                 [("0", "(base)", f"{b['validation']:.4g}")]
                 + [(str(k), esc(e["add"]), f"{e['validation']:.4g}")
                    for k, e in enumerate(g.get("sequence", []), 1)])
    left = (f"<p>Left unexplained above the noise floor: NRMSE "
            f"{g.get('unexplained_nrmse', float('nan')):.3g} "
            f"({100 * g.get('unexplained_share_of_gap', float('nan')):.0f} % of the gap).</p>"
            if g else "")
    shift = "".join(
        f"<li>held-out <code>{esc(k)}</code> {e['validation_range'][0]:.4g} to "
        f"{e['validation_range'][1]:.4g} {esc(e['unit'])}, fit data {e['fit_range'][0]:.4g} "
        f"to {e['fit_range'][1]:.4g} {esc(e['unit'])} "
        f"({100 * e['outside_share']:.0f} % of the held-out samples outside)</li>"
        for k, e in report.get("extrapolation", {}).items())
    shift = f"<p>Extrapolation:</p><ul>{shift}</ul>" if shift else ""
    va = report.get("velocity_alignment") or {}
    if va.get("applied"):
        # the records the fit and the held-out scores were computed on were moved
        shift += (f"<p>Motion channels: the velocity lagged the position by "
                  f"{va['lag_samples']:.2f} samples and was advanced by that much (with an "
                  f"acceleration differentiated from it) in every record before fitting.</p>")
    skipped = "".join(f"<li><code>{esc(k)}</code>: {esc(w)}</li>"
                      for k, w in report.get("skipped", {}).items())
    skipped = f"<p>Candidates not tried:</p><ul>{skipped}</ul>" if skipped else ""
    doc = PAGE_HEAD.format(title="frictionlab diagnosis") + f"""
<body><h1>Sim-to-real gap diagnosis</h1>
<p><b>Verdict: {html.escape(str(v['cause']))}</b> (held-out gap closed
{100 * v['gap_closed']:.1f} %). {html.escape(v.get('reason', ''))}</p>
<p>Base model <code>{html.escape(b['model'])}</code>: fit NRMSE {b['fit']:.4g}, held-out NRMSE
{b['validation']:.4g}, estimated noise floor {report['noise_floor']:.3g}.</p>
{shift}
<h2>Where the gap lies</h2>{where}{img('residuals')}
<h3>Bands of velocity, acceleration, position, load and time</h3>{bands}
<h3>Frequency</h3>{freq}
<h2>Which effect</h2>{which}{rows}{img('candidates')}{params_html}{skipped}
<h2>How far it shrinks</h2>{seq}{left}
<h2>Friction before and after</h2>{img('loops')}
</body></html>"""
    with open(path, "w") as fh:
        fh.write(doc)
