"""2-D lookup table over (position, current) with bilinear interpolation (``CombiTable2D``).

The voice-coil force map ``fmag(S, i)`` of seed 000 (Fig. 4: force against position and
current, from FEA and a bench test) is such a table. The paper's numbers are not printed, so
:func:`make_fmag_table` builds a smooth map with the properties the text states: the force is
"nearly proportional to the magnitude of the current" and changes mildly with position.

Interpolation is bilinear inside the grid and holds the edge values outside (no
extrapolation), like Modelica's ``CombiTable2D`` with ``extrapolation = HoldLastPoint``.
The numba kernel :func:`bilinear` is what plant steppers call; :class:`Table2D` is the
validated, vectorised Python face of the same data.

Examples
--------
>>> from plants.tables import make_fmag_table
>>> fmag = make_fmag_table()
>>> round(float(fmag(4e-3, 1.0)), 1)       # N at mid-stroke, 1 A
25.0
>>> i = fmag.inverse(4e-3, 25.0)            # current that gives 25 N there
>>> round(float(i), 2)
1.0
"""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["Table2D", "bilinear", "bilinear_inverse_y", "make_fmag_table", "fmag_analytic"]


@njit(cache=True, inline="always")
def _locate(grid, x):
    """Index k and weight w with x ~ grid[k] (1-w) + grid[k+1] w, clamped to the grid."""
    n = grid.size
    if x <= grid[0]:
        return 0, 0.0
    if x >= grid[n - 1]:
        return n - 2, 1.0
    lo = 0
    hi = n - 1
    while hi - lo > 1:  # bisection: grids are small and strictly increasing
        mid = (lo + hi) // 2
        if grid[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, (x - grid[lo]) / (grid[lo + 1] - grid[lo])


@njit(cache=True)
def bilinear(xg, yg, Z, x, y):
    """Bilinear interpolation of ``Z[len(xg), len(yg)]`` at (x, y); edge values held outside.

    Parameters
    ----------
    xg, yg : ndarray
        Strictly increasing grids (position [m], current [A] for the valve map).
    Z : ndarray, shape (len(xg), len(yg))
        Table values (force [N]).
    x, y : float
        Query point.
    """
    i, wx = _locate(xg, x)
    j, wy = _locate(yg, y)
    z0 = Z[i, j] * (1.0 - wy) + Z[i, j + 1] * wy
    z1 = Z[i + 1, j] * (1.0 - wy) + Z[i + 1, j + 1] * wy
    return z0 * (1.0 - wx) + z1 * wx


@njit(cache=True)
def bilinear_inverse_y(xg, yg, Z, x, target):
    """The y with ``bilinear(x, y) = target`` for a table increasing in y (piecewise linear).

    Returns the edge of the y-grid when the target lies outside the table's range at x
    (the actuator saturates).
    """
    n = yg.size
    i, wx = _locate(xg, x)
    prev = Z[i, 0] * (1.0 - wx) + Z[i + 1, 0] * wx
    if target <= prev:
        return yg[0]
    for j in range(1, n):
        cur = Z[i, j] * (1.0 - wx) + Z[i + 1, j] * wx
        if target <= cur:
            if cur == prev:
                return yg[j]
            return yg[j - 1] + (target - prev) / (cur - prev) * (yg[j] - yg[j - 1])
        prev = cur
    return yg[n - 1]


class Table2D:
    """Table ``z = f(x, y)`` on a rectangular grid, bilinear inside, edge values held outside.

    Parameters
    ----------
    x, y : array_like
        Strictly increasing grid vectors (at least 2 points each).
    values : array_like, shape (len(x), len(y))
        Table values.
    x_name, y_name, z_name : str
        Names with units, used in error messages and plots (e.g. ``"S [m]"``).
    """

    def __init__(self, x, y, values, *, x_name: str = "x", y_name: str = "y",
                 z_name: str = "z"):
        self.x = self._grid(x, x_name)
        self.y = self._grid(y, y_name)
        Z = np.ascontiguousarray(values, dtype=np.float64)
        if Z.shape != (self.x.size, self.y.size):
            raise ValueError(f"{z_name} table has shape {Z.shape}, expected "
                             f"({self.x.size}, {self.y.size}) = (len {x_name}, len {y_name})")
        if not np.all(np.isfinite(Z)):
            i, j = np.argwhere(~np.isfinite(Z))[0]
            raise ValueError(f"{z_name} table value at ({x_name}={self.x[i]:g}, "
                             f"{y_name}={self.y[j]:g}) is not finite")
        self.values = Z
        self.x_name, self.y_name, self.z_name = x_name, y_name, z_name

    @staticmethod
    def _grid(g, name):
        g = np.ascontiguousarray(g, dtype=np.float64).ravel()
        if g.size < 2:
            raise ValueError(f"grid {name} needs at least 2 points, got {g.size}")
        if not np.all(np.isfinite(g)):
            raise ValueError(f"grid {name} has a non-finite value at index "
                             f"{int(np.argmax(~np.isfinite(g)))}")
        d = np.diff(g)
        if np.any(d <= 0):
            k = int(np.argmax(d <= 0))
            raise ValueError(f"grid {name} must be strictly increasing: {name}[{k + 1}] = "
                             f"{g[k + 1]:g} <= {name}[{k}] = {g[k]:g}")
        return g

    def __call__(self, x, y):
        """Interpolated value(s) at (x, y) (broadcast arrays or scalars)."""
        xb, yb = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
        out = np.empty(xb.shape)
        fx, fy, fo = xb.ravel(), yb.ravel(), out.ravel()
        for k in range(fx.size):
            fo[k] = bilinear(self.x, self.y, self.values, fx[k], fy[k])
        return out if out.ndim else float(out)

    def inverse(self, x, target):
        """The y giving ``f(x, y) = target`` (table must increase in y); clamps to the grid."""
        if np.any(np.diff(self.values, axis=1) <= 0):
            raise ValueError(f"{self.z_name} table is not strictly increasing in "
                             f"{self.y_name}; it cannot be inverted")
        xb, tb = np.broadcast_arrays(np.asarray(x, float), np.asarray(target, float))
        out = np.empty(xb.shape)
        fx, ft, fo = xb.ravel(), tb.ravel(), out.ravel()
        for k in range(fx.size):
            fo[k] = bilinear_inverse_y(self.x, self.y, self.values, fx[k], ft[k])
        return out if out.ndim else float(out)

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(x grid, y grid, values) as contiguous float64 arrays, for numba steppers."""
        return self.x, self.y, self.values

    def __repr__(self) -> str:
        return (f"Table2D({self.z_name} over {self.x_name} [{self.x[0]:g}..{self.x[-1]:g}, "
                f"{self.x.size} pts] x {self.y_name} [{self.y[0]:g}..{self.y[-1]:g}, "
                f"{self.y.size} pts])")


def fmag_analytic(S, i, *, Kf: float = 25.0, S_mid: float = 4e-3, S_half: float = 6e-3,
                  position_drop: float = 0.06, i_sat: float = 30.0):
    """Smooth voice-coil force map [N] used to fill the table (seed 000 Fig. 4 properties).

    ``fmag = Kf (1 - position_drop ((S - S_mid)/S_half)^2) i / sqrt(1 + (i/i_sat)^2)``:
    proportional to current for |i| << i_sat (Lorentz force), strictly increasing in i, and
    weakest at the ends of the stroke where the coil leaves the Halbach array's field.

    Parameters
    ----------
    S : array_like
        Valve position (lift) [m].
    i : array_like
        Coil current [A].
    Kf : float
        Force constant at mid-stroke [N/A].
    S_mid, S_half : float
        Stroke centre and half-width of the field region [m].
    position_drop : float
        Relative force loss at ``|S - S_mid| = S_half`` [-] ("mild position dependence").
    i_sat : float
        Current scale of the mild saturation [A].
    """
    S = np.asarray(S, float)
    i = np.asarray(i, float)
    shape = 1.0 - position_drop * ((S - S_mid) / S_half) ** 2
    return Kf * shape * i / np.sqrt(1.0 + (i / i_sat) ** 2)


def make_fmag_table(*, S_min: float = -2e-3, S_max: float = 10e-3, nS: int = 25,
                    i_max: float = 10.0, ni: int = 41, **shape) -> Table2D:
    """Tabulate :func:`fmag_analytic` on a (position, current) grid (seed 000 Fig. 4 role).

    Parameters
    ----------
    S_min, S_max : float
        Position range [m] (covers the 0-8 mm lift with margin).
    nS, ni : int
        Grid points in position and current.
    i_max : float
        Current range is [-i_max, i_max] [A].
    **shape
        Keywords of :func:`fmag_analytic` (``Kf``, ``position_drop``, ...).

    Returns
    -------
    Table2D
        ``fmag(S [m], i [A]) -> force [N]``.
    """
    if not (S_max > S_min):
        raise ValueError(f"S_max = {S_max!r} must be > S_min = {S_min!r} [m]")
    if not i_max > 0:
        raise ValueError(f"i_max = {i_max!r} is out of bounds: must be > 0 [A]")
    if nS < 2 or ni < 2:
        raise ValueError(f"nS = {nS}, ni = {ni}: each grid needs at least 2 points")
    S = np.linspace(S_min, S_max, nS)
    i = np.linspace(-i_max, i_max, ni)
    F = fmag_analytic(S[:, None], i[None, :], **shape)
    return Table2D(S, i, F, x_name="S [m]", y_name="i [A]", z_name="fmag [N]")

