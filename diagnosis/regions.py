"""Where the gap lies: the residual's energy by regime, band and frequency.

A region's ``share`` is its fraction of the residual energy sum(r^2); its ``nrmse`` is the
local RMS(r) and its ``bias`` the local mean of r, both over std(F_measured) of the whole
record, so regions compare on one scale.
"""
from __future__ import annotations

import numpy as np

__all__ = ["regime_split", "band_splits", "frequency_split", "presliding_threshold"]


def presliding_threshold(data) -> float:
    """Speed below which the contact counts as pre-sliding / reversing [m/s]."""
    return 0.02 * float(np.percentile(np.abs(data.v), 99))


def _entry(label, mask, r, sd, total):
    n = int(mask.sum())
    if n == 0:
        return None
    e = float(np.sum(r[mask] ** 2))
    # the signed mean shows what energy cannot: a level the base fit split between two
    # regions sits above the model in one and below it in the other
    return {"label": label, "share": e / total if total > 0 else 0.0,
            "nrmse": float(np.sqrt(np.mean(r[mask] ** 2)) / sd),
            "bias": float(np.mean(r[mask]) / sd), "samples": n,
            "fraction_of_samples": n / r.size}


def regime_split(data, r) -> list[dict]:
    """Disjoint regimes: pre-sliding vs sliding x accelerating/decelerating x direction."""
    sd = float(np.std(data.F)) or 1.0
    total = float(np.sum(r ** 2))
    vt = presliding_threshold(data)
    pre = np.abs(data.v) < vt
    acc = data.a * data.v > 0
    out = []
    for pre_lab, pm in (("pre-sliding", pre), ("sliding", ~pre)):
        for acc_lab, am in (("accelerating", acc), ("decelerating", ~acc)):
            for d_lab, dm in (("v>0", data.v >= 0), ("v<0", data.v < 0)):
                e = _entry(f"{pre_lab}, {acc_lab}, {d_lab}", pm & am & dm, r, sd, total)
                if e:
                    out.append(e)
    return sorted(out, key=lambda e: -e["share"])


def band_splits(data, r, n: int = 4) -> list[dict]:
    """Quantile bands of |v|, |a|, position, load and time."""
    sd = float(np.std(data.F)) or 1.0
    total = float(np.sum(r ** 2))
    signals = {"|v|": (np.abs(data.v), "m/s"), "|a|": (np.abs(data.a), "m/s^2"),
               "x": (data.x, "m"), "t": (data.t, "s")}
    if data.load is not None:
        signals["load"] = (data.load, "N")
    out = []
    for name, (s, unit) in signals.items():
        edges = np.unique(np.quantile(s, np.linspace(0, 1, n + 1)))
        for lo, hi in zip(edges[:-1], edges[1:]):
            mask = (s >= lo) & ((s < hi) if hi < edges[-1] else (s <= hi))
            e = _entry(f"{name} in [{lo:.3g}, {hi:.3g}] {unit}", mask, r, sd, total)
            if e:
                e["signal"] = name
                out.append(e)
    return sorted(out, key=lambda e: -e["share"])


def frequency_split(data, r) -> list[dict]:
    """Residual energy in octave-like frequency bands (uniform sampling assumed)."""
    fs = 1.0 / data.dt
    R = np.abs(np.fft.rfft(r - np.mean(r))) ** 2
    f = np.fft.rfftfreq(r.size, d=data.dt)
    total = float(R[1:].sum()) or 1.0
    edges = [0.0] + [fs / 2 / 2 ** k for k in range(6, 0, -1)] + [fs / 2 + 1e-12]
    out = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        m = (f > lo) & (f <= hi) if lo > 0 else (f > 0) & (f <= hi)
        out.append({"label": f"{lo:.3g}-{min(hi, fs / 2):.3g} Hz",
                    "share": float(R[m].sum()) / total})
    return sorted(out, key=lambda e: -e["share"])
