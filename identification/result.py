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
        95 % confidence interval ``name -> (low, high)`` [parameter units], respecting each
        parameter's domain; which method gave it (Gauss-Newton on the log scale for
        positive parameters, or profile likelihood where Gauss-Newton is not trustworthy)
        and whether a side is open is in ``identifiability["intervals"]``.
    identifiability : dict or None
        :func:`identification.identifiability.assess_identifiability`: ``at_bound``,
        ``unidentified`` (names and ``"a+b"`` combinations), ``advice`` and details.
    fixed : dict
        Parameters held fixed by the caller (``fixed=``, ``--fix``, ``--static-from``).
    algorithm : str
    seed : int
    bounds : dict
        Search box ``name -> {lower, upper, log}``.
    message : str
    """

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        try:
            return self[name]
        except KeyError as exc:
            raise AttributeError(name) from exc

    __setattr__ = dict.__setitem__
    __delattr__ = dict.__delitem__

    # -- entries computed on first read (the identifiability report and its intervals) --
    def defer(self, keys, compute) -> None:
        """Compute ``keys`` with ``compute() -> {key: value}`` when one of them is first
        read (item, attribute, ``get``, ``items``, ``as_dict``, ``summary``).

        Parameters
        ----------
        keys : iterable of str
            The keys computed later.
        compute : callable
            ``compute() -> {key: value}``, called once.
        """
        self.__dict__["_deferred"] = (tuple(keys), compute)

    def _resolve(self, key=None) -> None:
        pending = self.__dict__.get("_deferred")
        if pending is None or (key is not None and key not in pending[0]):
            return
        del self.__dict__["_deferred"]
        values = pending[1]()
        for k in pending[0]:
            dict.__setitem__(self, k, values[k])

    def __getitem__(self, key):
        self._resolve(key)
        return dict.__getitem__(self, key)

    def get(self, key, default=None):
        self._resolve(key)
        return dict.get(self, key, default)

    def items(self):
        self._resolve()
        return dict.items(self)

    def values(self):
        self._resolve()
        return dict.values(self)

    def copy(self):
        self._resolve()
        return IdentificationResult(dict.items(self))

    def __reduce__(self):
        self._resolve()  # a pickle carries values, not the pending computation
        return (IdentificationResult, (dict(dict.items(self)),))

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
        """JSON text of :meth:`as_dict`; also written to ``path`` if given.

        Parameters
        ----------
        path : str or path, optional
            Write the text to this file too.
        indent : int
            JSON indentation.
        """
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
        ident = self.get("identifiability") or {}
        ivals = ident.get("intervals") or {}
        tags = {"gauss-newton": "GN", "gauss-newton (log scale)": "GN log",
                "profile likelihood": "profile"}
        for n, v in self["params"].items():
            extra = ""
            if n in ci and ci[n] is not None:
                e = ivals.get(n, {})
                op = e.get("open") or []
                meth = e.get("method", "")
                tag = tags.get(meth, "not alone" if meth.startswith("not identified")
                               else meth.split(",")[0])
                # an open side shows the search-box edge: the cost is flat up to it
                extra = (f"   95% CI [{'open ' if 'lower' in op else ''}{ci[n][0]:.5g}, "
                         f"{ci[n][1]:.5g}{' open' if 'upper' in op else ''}]"
                         + (f" ({tag})" if tag else ""))
            lines.append(f"  {n:<12s} = {v:<14.6g} {units.get(n, ''):<8s}{extra}")
        for n, v in (self.get("fixed") or {}).items():
            lines.append(f"  {n:<12s} = {float(v):<14.6g} {units.get(n, ''):<8s}   (fixed)")
        if ident:
            lines.extend(_identifiability_lines(ident))
        return "\n".join(lines)


def _identifiability_lines(ident) -> list[str]:
    """The identifiability report as summary lines."""
    out = ["identifiability:"]
    b = ident.get("bounds") or {}
    out.append("  at bound     : " + (", ".join(
        f"{n} ({d['side']} {d['kind']} {d['bound']:.4g})" for n, d in b.items()) or "none"))
    out.append("  unidentified : " + (", ".join(ident.get("unidentified") or []) or "none"))
    for c in ident.get("combinations") or []:
        shown = ", ".join(f"{k} = {q['value']:.5g} [{q['ci'][0]:.5g}, {q['ci'][1]:.5g}]"
                          for k, q in c["identified"].items())
        out.append(f"  combination  : {c['label']}: only {shown} identified")
    for r in ident.get("relations") or []:
        out.append(f"  relation     : {r['label']} ({r['values'][0]:.4g} < {r['values'][1]:.4g})")
    for note in ident.get("notes") or []:
        out.append(f"  note         : {note}")
    adv = ident.get("advice") or []
    if adv:
        out.append("  advice       :")
        out.extend(f"    - {a}" for a in adv)
    return out
