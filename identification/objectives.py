"""Objectives: parameter vectors -> simulated friction -> cost against the measurement.

The cost is the contract's NRMSE, ``RMS(F_model - F_measured) / std(F_measured)``, so every
algorithm, every objective and the reported ``fit_nrmse`` speak the same number.

* :class:`InProcessObjective` (fast path): one call of the law's numba population kernel
  (``model.simulate_population``) simulates the whole population in parallel.
* :class:`identification.cosim.CoSimObjective`: every evaluation runs FMUs through the
  co-simulation master (what the product promises); same interface.
"""
from __future__ import annotations

import numpy as np

from friction import base as _base
from friction.base import METHODS, FrictionModel
from friction.dataset import Dataset

__all__ = ["Objective", "InProcessObjective", "check_data"]


#: fewest samples a record must have to be fitted or scored (an NRMSE over fewer is noise)
MIN_SAMPLES = 10


def check_data(data, role: str = "fit") -> Dataset:
    """Validate an identification dataset; raise a clear one-line error on bad data.

    Parameters
    ----------
    data : Dataset
        The record.
    role : {"fit", "validation"}
        ``"validation"``: a held-out record, scored and not fitted. It needs
        :data:`MIN_SAMPLES` samples (refused as "too short to score") and a measured force
        with a spread (its NRMSE divides by it); it may be at rest throughout.
    """
    if role not in ("fit", "validation"):
        raise ValueError(f"role = {role!r}: must be 'fit' or 'validation'")
    if not isinstance(data, Dataset):
        raise TypeError(f"data must be a friction.dataset.Dataset (load one with "
                        f"friction.load_dataset), got {type(data).__name__}")
    what = "data" if role == "fit" else (
        f"validation data {data.name!r}" if data.name else "validation data")
    if role == "validation" and len(data) < MIN_SAMPLES:
        raise ValueError(f"{what} has {len(data)} samples: too short to score "
                         f"(need >= {MIN_SAMPLES})")
    for key in ("t", "v", "F"):
        arr = getattr(data, key)
        bad = ~np.isfinite(arr)
        if bad.any():
            i = int(np.argmax(bad))
            raise ValueError(f"{what}: {key}[{i}] = {arr[i]!r} is not finite (first bad sample)"
                             if role == "validation" else
                             f"data.{key}[{i}] = {arr[i]!r} is not finite (first bad sample)")
    if len(data) < MIN_SAMPLES:
        raise ValueError(f"data has {len(data)} samples: too few to identify anything "
                         f"(need >= {MIN_SAMPLES})")
    if role == "validation":
        if not np.std(data.F) > 0:
            raise ValueError(f"{what}: the measured force is constant, so its NRMSE is "
                             f"undefined (std(F) = 0)")
        return data
    if not np.std(data.F) > 0:
        raise ValueError("data.F is constant: nothing to fit (the measured friction force "
                         "has zero spread)")
    if not np.any(data.v != 0):
        raise ValueError("data.v is zero everywhere: the motion excites no friction")
    return data


class Objective:
    """Interface: ``costs(X)`` for physical parameter rows ``X[npop, D]`` -> ``cost[npop]``,
    ``predict(X)`` -> ``F[npop, N]``. ``parallel_inside`` says whether one call already uses
    all cores (then an executor adds nothing)."""
    parallel_inside = False
    names: list
    data: Dataset

    def predict(self, X) -> np.ndarray:  # pragma: no cover - interface
        """Predicted forces [N], one row per parameter set.

        Parameters
        ----------
        X : array_like, shape (npop, D)
            Parameter sets (physical values of ``names``), one per row.
        """
        raise NotImplementedError

    def costs(self, X) -> np.ndarray:
        """NRMSE of each parameter set against the measured force.

        Parameters
        ----------
        X : array_like, shape (npop, D)
            Parameter sets (physical values), one per row.
        """
        F = self.predict(X)
        return self.costs_from_forces(F)

    def costs_from_forces(self, F) -> np.ndarray:
        """NRMSE of each row of predicted forces against the measured force.

        Parameters
        ----------
        F : ndarray, shape (npop, N)
            Predicted forces [N], one row per parameter set.
        """
        d = F - self.data.F[None, :]
        c = np.sqrt(np.mean(d * d, axis=1)) / self._sd
        return np.where(np.isfinite(c), c, np.inf)

    def residuals(self, x) -> np.ndarray:
        """Scaled residual vector of one parameter set: ``sum(r**2) = nrmse**2``.

        Parameters
        ----------
        x : array_like, shape (D,)
            One parameter set (physical values).
        """
        F = self.predict(np.atleast_2d(x))[0]
        return (F - self.data.F) * self._rscale

    def jacobian(self, x):
        """Analytic Jacobian of :meth:`residuals` with respect to the physical parameters
        (``N x D``), or ``None`` when the objective has none (the problem then takes
        finite differences).

        Parameters
        ----------
        x : array_like, shape (D,)
            One parameter set (physical values).
        """
        return None

    def has_jacobian(self) -> bool:
        """Whether :meth:`jacobian` (and :meth:`normal_equations`) give analytic values
        (for every parameter set or for none)."""
        return False

    def normal_equations(self, x):
        """``(sum r^2, J^T r, J^T J)`` of the scaled residual at one parameter set (physical
        values), without an ``N x D`` Jacobian in memory, or ``None`` when the objective
        has no analytic Jacobian.

        Parameters
        ----------
        x : array_like, shape (D,)
            One parameter set (physical values).
        """
        return None

    @property
    def _sd(self) -> float:
        # computed once per measured array (an O(N) pass and temporary otherwise on every
        # residual evaluation)
        F = self.data.F
        cached = self.__dict__.get("_sd_cache")
        if cached is None or cached[0] is not F:
            cached = self.__dict__["_sd_cache"] = (F, float(np.std(F)))
        return cached[1]

    @property
    def _rscale(self) -> float:
        return 1.0 / (self._sd * np.sqrt(len(self.data)))


class InProcessObjective(Objective):
    """NRMSE of a friction law simulated along the measured motion (numba population kernel).

    Parameters
    ----------
    model : FrictionModel
        The law; its current values fix every parameter not in ``names``.
    data : Dataset
        Measured motion (t, v, and a/load/x if the law needs them) and friction force F.
    names : list of str
        Identified parameters, the columns of ``X``.
    method : {"exact", "euler"}
        Bristle update (``exact``: stable at any step).
    start : {"rest", "record"}
        Initial state of each simulation: the law at rest (zeros, the fit's default), or
        the state consistent with the record's first samples, its motion and its measured
        force (:meth:`friction.base.FrictionModel.record_start_state`), which a held-out
        record that starts in motion needs (from rest a stiff, damped bristle would spike).
    """
    parallel_inside = True

    def __init__(self, model: FrictionModel, data: Dataset, names, method: str = "exact",
                 start: str = "rest"):
        if start not in ("rest", "record"):
            raise ValueError(f"start = {start!r}: must be 'rest' or 'record'")
        self.model = model
        # a start from the record is the held-out protocol: it is scored, not fitted
        self.data = check_data(data, role="validation" if start == "record" else "fit")
        self.names = list(names)
        self.method = method
        self.start = start
        self._inputs = dict(a=data.a, load=data.load, x=data.x)
        if "load" in model.extra_inputs and data.load is None:
            raise ValueError(f"model {model.name!r} needs a load column [N] in the data")

    def predict(self, X) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        if X.shape[0] == 1 or self.start != "rest":
            # one set (least-squares residual): the serial kernel, no thread-pool launch;
            # same update code as the population kernel, so the same numbers. A start from
            # the record depends on each row's values: row by row as well
            m = self.model
            t, v, a, load, x = self._prepared()
            rows = []
            for row in X:
                theta = m.population_theta(self.names, row[None, :])[0]
                F, _ = m._kernel(t, v, a, load, x, theta, METHODS[self.method],
                                 self._state0(row, t, v, a, load, x))
                rows.append(F)
            return np.array(rows)
        return self.model.simulate_population(self.data.t, self.data.v, self.names, X,
                                              method=self.method, **self._inputs)

    def costs(self, X) -> np.ndarray:
        """Costs of a population; a law with a fused kernel (``_population_sse_kernel``,
        the classic LuGre) never holds the population's forces (memory O(npop), not
        O(npop N)), otherwise as :meth:`Objective.costs`."""
        # the law's own class, not inherited: a subclass changes the equations
        kernel = None
        if "_population_sse_kernel" in vars(type(self.model)):
            kernel = type(self.model)._population_sse_kernel
        if kernel is None or self.start != "rest" \
                or type(self).predict is not InProcessObjective.predict:
            return super().costs(X)
        X = np.atleast_2d(np.asarray(X, float))
        t, v, a, load, xx = self._prepared()
        Theta = self.model.population_theta(self.names, X)
        if _base.SERIAL_POPULATIONS:  # a forked worker: no parallel kernel
            kernel = type(self.model)._serial_sse_kernel
        sse = kernel(t, v, Theta, METHODS[self.method], self.data.F)
        c = np.sqrt(sse / t.size) / self._sd
        return np.where(np.isfinite(c), c, np.inf)

    def residuals(self, x) -> np.ndarray:
        F = self.predict(np.atleast_2d(x))[0]  # a fresh array: worked on in place
        F -= self.data.F
        F *= self._rscale
        return F

    def has_jacobian(self) -> bool:
        """The law has a sensitivity kernel (``_sensitivity_kernel``: the classic LuGre)
        covering every identified name, the simulations start at rest (a start from the
        record depends on the parameters) and :meth:`predict` is this class's own (a
        subclass that changes the prediction would need its own derivative)."""
        cols = self.__dict__.get("_jac_cols")
        if cols is None:
            m = self.model
            cols = False
            # the law's own class, not inherited: a subclass changes the equations
            own = vars(type(m))
            if own.get("_sensitivity_kernel") is not None \
                    and own.get("_normal_equations_kernel") is not None \
                    and self.start == "rest" \
                    and type(self).predict is InProcessObjective.predict:
                try:
                    cols = m.jacobian_columns(self.names)
                except KeyError:
                    cols = False
            self._jac_cols = cols
        return cols is not False

    def jacobian(self, x):
        """Scaled residual Jacobian ``N x D`` at one parameter set ``x`` (physical values
        of ``names``) from the law's forward sensitivities (one pass of
        :func:`friction.lugre.lugre_sensitivity_run`), or ``None`` where
        :meth:`has_jacobian` is False (the problem then takes finite differences)."""
        if not self.has_jacobian():
            return None
        m = self.model
        kernel = type(m)._sensitivity_kernel
        cols = self._jac_cols
        t, v, a, load, xx = self._prepared()
        theta = m.population_theta(self.names, np.atleast_2d(np.asarray(x, float)))[0]
        F = np.empty(t.size)
        J = np.empty((t.size, len(self.names)))
        kernel(t, v, theta, METHODS[self.method], float(m.initial_state()[0]), cols, F, J)
        J *= self._rscale
        return J

    def normal_equations(self, x):
        """``(sum r^2, J^T r, J^T J)`` of the scaled residuals at one parameter set ``x``
        (physical values of ``names``) in one forward-sensitivity pass
        (:func:`friction.lugre.lugre_normal_equations`: memory O(D^2) however long the
        record), or ``None`` where :meth:`has_jacobian` is False."""
        if not self.has_jacobian():
            return None
        kernel, t, v, method, z0, cols, Fm, scale = self._sensitivity_setup()
        theta = self._theta_of(x)
        D = len(self.names)
        H = np.zeros((D, D))
        G = np.zeros(D)
        sse = kernel(t, v, theta, method, z0, cols, Fm, scale, H, G)
        return float(sse), G, H

    def _sensitivity_setup(self):
        """What every sensitivity pass takes besides theta (computed once per record)."""
        st = self.__dict__.get("_sens_setup")
        if st is None or st[6] is not self.data.F:
            m = self.model
            t, v = self._prepared()[:2]
            st = self._sens_setup = (type(m)._normal_equations_kernel, t, v,
                                     METHODS[self.method], float(m.initial_state()[0]),
                                     self._jac_cols, self.data.F, self._rscale)
        return st

    def _theta_of(self, x) -> np.ndarray:
        """:meth:`friction.base.FrictionModel.population_theta` of one row (its index
        arithmetic cached: a least-squares run asks for it once per pass)."""
        idx = self.__dict__.get("_theta_idx")
        m = self.model
        if idx is None:
            layout = {n: i for i, n in enumerate(m.theta_layout)}
            dst, src = [], []
            for j, n in enumerate(self.names):
                dst.append(layout[n])
                src.append(j)
                twin = m.twins.get(n)
                if twin is not None and getattr(m.params, twin, None) is None \
                        and twin not in self.names:
                    dst.append(layout[twin])
                    src.append(j)
            idx = self._theta_idx = (np.array(dst, np.int64), np.array(src, np.int64))
        theta = m.theta.copy()
        theta[idx[0]] = np.asarray(x, float).ravel()[idx[1]]
        return theta

    def _state0(self, row, t, v, a, load, x) -> np.ndarray:
        m = self.model
        if self.start == "rest":
            return m.initial_state()
        try:
            trial = m.with_values(**dict(zip(self.names, map(float, row))))
        except (ValueError, TypeError):  # values the law rejects: no steady state to take
            return m.initial_state()
        return trial._start_from(t, v, a, load, x, float(self.data.F[0]))

    def _prepared(self):
        if getattr(self, "_prep", None) is None:
            self._prep = self.model._inputs(self.data.t, self.data.v, **self._inputs)
        return self._prep
