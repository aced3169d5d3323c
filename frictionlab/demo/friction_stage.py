"""Demo stage of the friction laws: Stribeck curves, hysteresis loops and the modified LuGre.

Figures written into the demo folder:

* ``friction_laws.png``: steady-state curves of every registered law (each normalised to its
  own force and speed scale, so a forging press and a micro-stage share one plot) and the
  LuGre pre-sliding hysteresis loops;
* ``friction_velocity_loops.png``: LuGre friction-velocity hysteresis at several frequencies;
* ``modified_lugre_loops.png``: the seed-000 valve law: clockwise vertical friction-velocity
  loops from the acceleration part F_d at 5/10/20 Hz, the switch Gamma(v) against the Euler
  critical velocity, and explicit Euler at 20 kHz with and without Gamma.
"""
from __future__ import annotations

import os

import numpy as np

from friction import MODELS, make_model
from friction.numerics import euler_critical_velocity

__all__ = ["run_stage"]


def _default_inputs(name, v):
    kw = {}
    model_cls = MODELS[name]
    if "load" in model_cls.extra_inputs:
        kw["load"] = np.full(v.size, 1.0)
    return kw


def _stribeck_panel(ax, laws):
    for name in sorted(MODELS):
        model = make_model(name)
        scale = getattr(model, "velocity_scale", lambda: 0.02)()
        v = np.linspace(-scale, scale, 801)
        Fss = model.steady_state(v, **_default_inputs(name, v))
        Fmax = float(np.max(np.abs(Fss))) or 1.0
        ax.plot(v / scale, Fss / Fmax, ls="--" if name == "stribeck" else "-",
                label=f"{name} ({scale:.2g} m/s, {Fmax:.3g} N)")
        laws[name] = {"params": {k: (val if not isinstance(val, float) else float(val))
                                 for k, val in model.params.as_dict().items()},
                      "velocity_scale": float(scale), "force_scale": Fmax}
    ax.set(xlabel="velocity / law's speed scale [-]", ylabel="F_ss / max |F_ss| [-]",
           title="Stribeck curves (defaults, normalised)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)


def _modified_lugre_figure(out, plt):
    """Valve law of seed 000 (defaults): vertical loops, Gamma and the Euler instability."""
    ml = make_model("modified_lugre")
    p = ml.params
    classic_ml = make_model("modified_lugre", f_a=0.0)  # same law without F_d
    lg = make_model("lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2, Fc=p.Fc,
                    Fs=p.Fs, vs=p.vs, alpha=p.alpha)
    h = 5e-5
    vcr = euler_critical_velocity(lg, h)
    info = {"euler_critical_velocity": vcr, "h": h, "v1": p.v1, "v2": p.v2, "loops": {}}

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    amp = 2e-3  # valve stroke amplitude [m]
    for f, colour in ((5.0, "C0"), (10.0, "C1"), (20.0, "C2")):
        w = 2 * np.pi * f
        t = np.arange(0, 2.0 / f, h)
        v = amp * w * np.sin(w * t)
        a = amp * w * w * np.cos(w * t)
        F = ml.simulate(t, v, a=a)
        F0 = classic_ml.simulate(t, v, a=a)
        keep = t >= 1.0 / f
        axes[0].plot(v[keep], F[keep], color=colour, label=f"{f:g} Hz (|a| <= {amp * w * w:.0f} "
                     "m/s^2)")
        axes[0].plot(v[keep], F0[keep], color=colour, lw=0.8, ls=":")
        # vertical loop opening at mid speed: accelerating minus decelerating branch
        vm = 0.5 * amp * w
        up = keep & (a * v > 0)
        dn = keep & (a * v < 0)
        iu = np.argmin(np.abs(v[up] - vm))
        idn = np.argmin(np.abs(v[dn] - vm))
        info["loops"][f"{f:g}Hz"] = {"v_max": amp * w,
                                     "opening_at_half_speed": float(F[up][iu] - F[dn][idn])}
    vv = np.linspace(-0.2, 0.2, 200)
    axes[0].plot(vv, ml.steady_state(vv), "k--", lw=1, label="steady state (Eq. 5)")
    axes[0].set(xlabel="velocity [m/s]", ylabel="friction [N]",
                title="modified LuGre: clockwise vertical loops from F_d\n"
                      f"(2 mm stroke; dotted: f_a = 0)")
    axes[0].legend(fontsize=7)
    axes[0].grid(alpha=0.3)

    speed = np.linspace(0, 0.6, 601)
    for form, ls in (("logistic", "-"), ("cosine", "--")):
        axes[1].plot(speed, make_model("modified_lugre", gamma_form=form).gamma_switch(speed),
                     ls, label=f"Gamma ({form})")
    axes[1].axvline(vcr, color="r", lw=1, label=f"Euler v_cr = {vcr:.3f} m/s (h = 50 us)")
    axes[1].axvline(2 * vcr, color="r", lw=1, ls=":", label="growth 2 v_cr")
    axes[1].set(xlabel="|v| [m/s]", ylabel="Gamma(v)", title="switch function (Eq. 10)")
    axes[1].legend(fontsize=7)
    axes[1].grid(alpha=0.3)

    # 20 Hz, 5 mm amplitude: v_max = 0.63 m/s > 2 v_cr, explicit Euler as the paper runs it
    f, A = 20.0, 5e-3
    w = 2 * np.pi * f
    t = np.arange(0, 0.1, h)
    v = A * w * np.sin(w * t)
    a = A * w * w * np.cos(w * t)
    with np.errstate(all="ignore"):
        _, Zc = lg.simulate(t, v, method="euler", return_state=True)
    _, Zm = ml.simulate(t, v, a=a, method="euler", return_state=True)
    _, Zx = ml.simulate(t, v, a=a, return_state=True)
    zmax = lg.z_max()
    zc = np.clip(Zc[:, 0] / zmax, -3, 3)
    axes[2].plot(t * 1e3, zc, lw=0.8, label="classic LuGre, Euler (clipped at +-3)")
    axes[2].plot(t * 1e3, Zm[:, 0] / zmax, label="modified LuGre, Euler")
    axes[2].plot(t * 1e3, Zx[:, 0] / zmax, "k:", label="modified LuGre, exact update")
    axes[2].set(xlabel="time [ms]", ylabel="z / (Fs/sigma0)", ylim=(-3.2, 3.2),
                title=f"observer at 20 kHz, {f:g} Hz x {A * 1e3:g} mm (v_max = {A * w:.2f} m/s)")
    axes[2].legend(fontsize=7)
    axes[2].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "modified_lugre_loops.png"), dpi=110)
    plt.close(fig)
    finite = np.isfinite(Zc[:, 0])
    info["classic_euler_max_z_over_zmax"] = float(np.max(np.abs(Zc[finite, 0])) / zmax)
    info["classic_euler_finite"] = bool(finite.all())
    info["modified_euler_max_z_over_zmax"] = float(np.max(np.abs(Zm[:, 0])) / zmax)
    return info


def run_stage(out: str, summary: dict, quick: bool = False) -> None:
    """Write the friction-law figures into ``out`` and their names into ``summary``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    laws = {}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    _stribeck_panel(axes[0], laws)

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

    figures = ["friction_laws.png", "friction_velocity_loops.png"]
    entry = {"models": sorted(MODELS), "figures": figures, "laws": laws}
    entry["modified_lugre"] = _modified_lugre_figure(out, plt)
    figures.append("modified_lugre_loops.png")
    summary["friction_laws"] = entry
