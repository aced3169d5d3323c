"""Demo stage of the friction laws: Stribeck curves and hysteresis loops as PNG files."""
from __future__ import annotations

import os

import numpy as np

from . import MODELS, make_model


def _default_inputs(name, t, v):
    kw = {}
    model_cls = MODELS[name]
    if "load" in model_cls.extra_inputs:
        kw["load"] = np.full(t.size, 1.0)
    return kw


def run_stage(out: str, summary: dict, quick: bool = False) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    laws = {}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in sorted(MODELS):
        model = make_model(name)
        scale = getattr(model, "velocity_scale", lambda: 0.02)()
        v = np.linspace(-scale, scale, 801)
        kw = _default_inputs(name, v, v)
        Fss = model.steady_state(v, **kw)
        axes[0].plot(v, Fss, label=name)
        laws[name] = {"params": {k: (val if not isinstance(val, float) else float(val))
                                 for k, val in model.params.as_dict().items()}}
    axes[0].set(xlabel="velocity v [m/s]", ylabel="steady-state friction F_ss [N]",
                title="Stribeck curves (defaults)")
    axes[0].legend(fontsize=8)
    axes[0].grid(alpha=0.3)

    # pre-sliding hysteresis of the classic LuGre: small sinusoidal displacement
    lugre = make_model("lugre")
    zmax = lugre.z_max()
    for amp in (0.2, 0.6, 1.5, 3.0):
        f = 1.0
        t = np.linspace(0, 3.0, 30001)
        x = amp * zmax * np.sin(2 * np.pi * f * t)
        v = amp * zmax * 2 * np.pi * f * np.cos(2 * np.pi * f * t)
        F = lugre.simulate(t, v)
        keep = t >= 1.0
        axes[1].plot(x[keep] * 1e6, F[keep], label=f"{amp:g} x Fs/sigma0")
    axes[1].set(xlabel="displacement x [um]", ylabel="friction F [N]",
                title="LuGre pre-sliding hysteresis loops")
    axes[1].legend(fontsize=8)
    axes[1].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "friction_laws.png"), dpi=110)
    plt.close(fig)

    # friction-velocity loops at several frequencies (sliding hysteresis)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for f in (1.0, 5.0, 20.0):
        t = np.linspace(0, 3 / f, 6001)
        v = 2e-3 * np.sin(2 * np.pi * f * t)
        F = lugre.simulate(t, v)
        keep = t >= 1 / f
        ax.plot(v[keep] * 1e3, F[keep], label=f"{f:g} Hz")
    ax.plot(np.linspace(-2, 2, 200), lugre.steady_state(np.linspace(-2e-3, 2e-3, 200)), "k--",
            lw=1, label="steady state")
    ax.set(xlabel="velocity [mm/s]", ylabel="friction [N]",
           title="LuGre friction-velocity hysteresis")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "friction_velocity_loops.png"), dpi=110)
    plt.close(fig)
    summary["friction_laws"] = {"models": sorted(MODELS),
                                "figures": ["friction_laws.png", "friction_velocity_loops.png"]}
