"""Figures and self-contained HTML report of a trajectory-level diagnosis."""
from __future__ import annotations

import numpy as np

__all__ = ["trajectory_figures", "write_trajectory_html"]


def _png(fig) -> str:
    from .report_html import _png as png
    return png(fig)


def trajectory_figures(report) -> dict[str, str]:
    """Base64 PNGs of a trajectory report: held-out tracking error measured / base / named
    effect, the base residual against velocity, acceleration, position and time, and the
    ranked candidates. Curves are re-simulated in-process (same equations as either engine).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .engines import TrajectoryModel, _PlantEngine  # the report re-runs the model

    d = report._data
    plant, ctx = d["plant"], d["ctx"]
    case, kin = d["validation"][0], d["val_data"][0]
    tm = TrajectoryModel(plant, _PlantEngine(plant))
    rec, m = case.record, case.mask

    def curve(setup_u):
        law, pp, delay, _ = setup_u[0].build(setup_u[1], ctx)
        return tm._output(law, pp, rec, case.stop, delay)[0]

    y_base = curve(report._models["base"])
    cause = report["verdict"]["cause"]
    best = report._models.get(cause) or (report._models.get(report["effects"][0]["name"])
                                         if report["effects"] else None)
    ref = case.ref if case.ref is not None else np.zeros_like(rec.y)
    out = {}
    fig, ax = plt.subplots(figsize=(11, 4))
    ax.plot(rec.t[m], (ref - rec.y)[m], color="0.5", lw=1, label="measured")
    ax.plot(rec.t[m], (ref - y_base)[m], lw=1, label="base model")
    if best is not None:
        ax.plot(rec.t[m], (ref - curve(best))[m], lw=1,
                label=f"with {cause if cause in report._models else report['effects'][0]['name']}")
    ax.set(xlabel="time [s]", ylabel="tracking error [m]",
           title=f"held-out record {rec.name}: tracking error, re-simulated {plant.name}")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out["tracking"] = _png(fig)

    r = (rec.y - y_base)[m]
    sig = [("velocity v [m/s]", kin.v[m]), ("acceleration a [m/s^2]", kin.a[m]),
           ("position x [m]", kin.x[m]), ("time t [s]", kin.t[m])]
    fig, axes = plt.subplots(1, len(sig), figsize=(3.6 * len(sig), 3.2), sharey=True)
    for ax, (lab, sgl) in zip(axes, sig):
        ax.plot(sgl, r, ".", ms=1.5, alpha=0.4)
        ax.set_xlabel(lab)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("held-out residual y_meas - y_model [m]")
    fig.tight_layout()
    out["residuals"] = _png(fig)

    from .report_html import candidates_png
    out["candidates"] = candidates_png(report, "candidate effects in the re-simulated plant, "
                                               "ranked")
    return out


def write_trajectory_html(report, path) -> None:
    """Self-contained HTML report of a trajectory-level diagnosis."""
    import html

    from .report_html import PAGE_HEAD, contract_tables, img_tag
    figs = trajectory_figures(report)
    b, v = report["baseline"], report["verdict"]
    where, rows = contract_tables(report)
    img = lambda k: img_tag(figs[k])
    doc = PAGE_HEAD.format(title="frictionlab trajectory diagnosis") + f"""
<body><h1>Sim-to-real gap diagnosis, trajectory level ({html.escape(report['plant'])})</h1>
<p><b>Verdict: {html.escape(str(v['cause']))}</b> (held-out gap closed
{100 * v['gap_closed']:.1f} %). {html.escape(v.get('reason', ''))}</p>
<p>Base model <code>{html.escape(b['model'])}</code> in the plant (engine
{html.escape(report['engine'])}): fit NRMSE {b['fit']:.4g}, held-out NRMSE {b['validation']:.4g}
({html.escape(b['normalised_by'])}), noise floor {report['noise_floor']:.3g}.</p>
{img('tracking')}
<h2>Where the gap lies</h2>{where}{img('residuals')}
<h2>Which effect</h2>{rows}{img('candidates')}
</body></html>"""
    with open(path, "w") as fh:
        fh.write(doc)
