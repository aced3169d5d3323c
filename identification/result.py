"""The result of an identification (``scipy.integrate.OdeResult`` style: a dict with
attribute access)."""
from __future__ import annotations

import json
import math

import numpy as np

__all__ = ["IdentificationResult"]


def _plain(obj):
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _plain(obj.tolist())
    if isinstance(obj, (np.floating, float)):
        f = float(obj)
        return f if math.isfinite(f) else None
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (np.bool_,)):
        return bool(obj)
    return obj


class IdentificationResult(dict):
    """Outcome of :func:`identification.identify`.

    Attributes
    ----------
    params : dict
        Identified parameter values [SI units], by name.
    model : FrictionModel
        The fitted law (all parameters, identified ones replaced).
    fit_nrmse : float
        NRMSE on the fitted data (RMS error / std of measured force).
    validation_nrmse : float or None
        NRMSE on the validation data, if given.
    cost_history : list of float
        Best cost after each iteration / stage.
    trace : list of [evaluations, seconds, best cost]
        Every improvement of the best cost (time-to-target analyses).
    n_evals : int
        Number of simulations (one per parameter set).
    wall_time : float
        Seconds.
    ci : dict or None
        95 % confidence interval ``name -> (low, high)`` where the method gives one
        (least squares: Gauss-Newton covariance from the Jacobian).
    algorithm : str
    seed : int
    bounds : dict
        Search box ``name -> {lower, upper, log}``.
    message : str
    """

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError as exc:
            raise AttributeError(name) from exc

    __setattr__ = dict.__setitem__
    __delattr__ = dict.__delitem__

    def __repr__(self):
        keys = ["algorithm", "params", "fit_nrmse", "validation_nrmse", "n_evals", "wall_time"]
        body = ",\n".join(f"  {k}={self.get(k)!r}" for k in keys)
        return f"IdentificationResult(\n{body})"

    def as_dict(self) -> dict:
        """JSON-ready dict (the fitted model as its registry name and full parameter set)."""
        d = {k: v for k, v in self.items() if k != "model"}
        m = self.get("model")
        if m is not None:
            d["model"] = {"name": m.name, "params": m.params.as_dict()}
        return _plain(d)

    def to_json(self, path=None, indent: int = 2) -> str:
        """JSON text of :meth:`as_dict`; also written to ``path`` if given."""
        text = json.dumps(self.as_dict(), indent=indent)
        if path is not None:
            with open(path, "w") as fh:
                fh.write(text + "\n")
        return text

    def summary(self) -> str:
        """Readable multi-line summary (what the CLI prints)."""
        lines = [f"algorithm   : {self.get('algorithm')} (seed {self.get('seed')})",
                 f"model       : {self['model'].name if self.get('model') is not None else '?'}",
                 f"fit NRMSE   : {self.get('fit_nrmse'):.4g}"]
        if self.get("validation_nrmse") is not None:
            lines.append(f"valid NRMSE : {self['validation_nrmse']:.4g}")
        lines.append(f"evaluations : {self.get('n_evals')}   wall time: {self.get('wall_time'):.2f} s")
        lines.append("parameters  :")
        units = {}
        if self.get("model") is not None:
            units = {i.name: i.unit for i in self["model"].Params.info()}
        ci = self.get("ci") or {}
        for n, v in self["params"].items():
            extra = ""
            if n in ci and ci[n] is not None:
                extra = f"   95% CI [{ci[n][0]:.5g}, {ci[n][1]:.5g}]"
            lines.append(f"  {n:<12s} = {v:<14.6g} {units.get(n, ''):<8s}{extra}")
        return "\n".join(lines)
