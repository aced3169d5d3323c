"""The seeds' swarm metaheuristics, as ``../shared/spec/EQUATIONS.md`` gives them.

All work in the unit cube (``a_l = 0, b_l = 1`` in the paper's notation), so Visual, Step and
the flight radius are fractions of each parameter's search range (log-scaled where the
parameter is). Each iteration evaluates its candidates as whole populations (one numba call
per batch) instead of fish by fish: the behaviours are computed synchronously from the
previous iteration's swarm, the usual parallel form of these algorithms.

* :class:`AFSA` / :class:`IAFSA`: artificial fish swarm (SHAO, seed 000; EQUATIONS A.5-A.6).
* :class:`FFOA` / :class:`IFFOA`: fruit-fly optimisation (YU, seed 002; EQUATIONS B.3-B.4).
* :class:`ChaoticPSO`: inertia-weighted PSO with chaotic disturbance (seed 001 Eqs. 9-14).
"""
from __future__ import annotations

import numpy as np

from .base import Algorithm, chaotic_sequence

__all__ = ["AFSA", "IAFSA", "FFOA", "IFFOA", "ChaoticPSO", "ALGORITHM_CLASSES"]


def _unit(d):
    n = np.linalg.norm(d, axis=-1, keepdims=True)
    return d / np.where(n > 0, n, 1.0)


class AFSA(Algorithm):
    """Plain artificial fish swarm: preying (18)-(19), swarming (20), following (21), random
    move (22), bulletin. Crowd test in SHAO's ratio form ``n_f / n < eta`` (EQUATIONS A.5), or
    the classical food-per-fish test ``Y / n_f < eta Y_i`` with ``crowd_test="food"`` (D.2)."""
    name = "afsa"
    defaults = dict(n_fish=50, step_length=0.5, visual=0.6, try_number=3, eta=0.7, max_iter=1000,
                    crowd_test="ratio")
    source = "SHAO 2018 (seed 000) Eqs. 18-22; Li Xiao-lei AFSA"
    improved = False

    def start(self, problem, rng, u0):
        X = rng.random((self.n_fish, problem.dim))
        X[0] = u0  # the model's current values join the school
        Y = problem.evaluate(X)
        return {"X": X, "Y": Y, "iteration": 0, "bulletin": [float(np.min(Y))],
                "ban": 0, "info": {}}

    def _move(self, X, target, rng):
        return np.clip(X + rng.random((len(X), 1)) * self.step_length * _unit(target - X), 0.0, 1.0)

    def step(self, problem, rng, state):
        X, Y = state["X"], state["Y"]
        n, D = X.shape
        vis = self.visual
        # neighbourhoods: box of half-width Visual_l around each fish (vector Visual)
        close = np.all(np.abs(X[:, None, :] - X[None, :, :]) < vis, axis=2)
        np.fill_diagonal(close, False)
        nf = close.sum(axis=1)
        if self.crowd_test == "ratio":  # SHAO: neighbours / population below eta
            crowd_ok = (nf > 0) & (nf / n < self.eta)
        elif self.crowd_test == "food":  # classical (D.2), minimisation: Y_c / n_f < eta Y_i
            crowd_ok = nf > 0  # applied per behaviour below
        else:
            raise ValueError(f"crowd_test = {self.crowd_test!r}: use 'ratio' or 'food'")
        # swarming: centre of the neighbours
        centre = np.where(nf[:, None] > 0, (close @ X) / np.maximum(nf, 1)[:, None], X)
        # following: best neighbour
        Ymask = np.where(close, Y[None, :], np.inf)
        jbest = np.argmin(Ymask, axis=1)
        ybest = Ymask[np.arange(n), jbest]
        newX, newY = X.copy(), Y.copy()
        done = np.zeros(n, bool)
        idx = np.flatnonzero(crowd_ok)
        if idx.size:
            Yc = problem.evaluate(centre[idx])
            Xs = self._move(X[idx], centre[idx], rng)
            Xf = self._move(X[idx], X[jbest[idx]], rng)
            use_s = Yc < Y[idx]
            use_f = ybest[idx] < Y[idx]
            if self.crowd_test == "food":
                use_s &= Yc / nf[idx] < self.eta * Y[idx]
                use_f &= ybest[idx] / nf[idx] < self.eta * Y[idx]
            cand_idx = np.concatenate([idx[use_s], idx[use_f]])
            cand = np.vstack([Xs[use_s], Xf[use_f]]) if cand_idx.size else np.empty((0, D))
            if cand_idx.size:
                Yn = problem.evaluate(cand)
                # each fish keeps the better of its swarm / follow moves
                for k, i in enumerate(cand_idx):
                    if not done[i] or Yn[k] < newY[i]:
                        newX[i], newY[i] = cand[k], Yn[k]
                        done[i] = True
        # preying for the rest: up to try_number tries, then a random move
        todo = np.flatnonzero(~done)
        for _ in range(self.try_number):
            if not todo.size:
                break
            Xj = np.clip(X[todo] + vis * (2 * rng.random((todo.size, D)) - 1), 0.0, 1.0)
            Yj = problem.evaluate(Xj)
            ok = Yj < Y[todo]
            if ok.any():
                Xm = self._move(X[todo[ok]], Xj[ok], rng)
                Ym = problem.evaluate(Xm)
                newX[todo[ok]], newY[todo[ok]] = Xm, Ym
            todo = todo[~ok]
        if todo.size:
            Xr = np.clip(X[todo] + vis * (2 * rng.random((todo.size, D)) - 1), 0.0, 1.0)
            newX[todo], newY[todo] = Xr, problem.evaluate(Xr)
        state["X"], state["Y"] = newX, newY
        state["iteration"] += 1
        state["bulletin"].append(float(min(np.min(newY), state["bulletin"][-1])))
        if self.improved:
            self._improve(problem, rng, state)
        return state

    def _improve(self, problem, rng, state):  # IAFSA only
        pass


class IAFSA(AFSA):
    """Improved AFSA (SHAO): plain AFSA plus Gauss mutation of the 10 worst fish when the
    bulletin improves by less than ``eps`` over 10 iterations (then a 20-iteration ban, Eq. 23
    in normalised coordinates with scale ``mutation_scale``), and chaotic search around the
    best fish (Eqs. 24-26) when the bulletin is unchanged for 10 iterations."""
    name = "iafsa"
    defaults = dict(AFSA.defaults, eps=5e-6, stall=10, n_mutate=10, ban=20,
                    mutation_scale=0.3, max_chaos=3000, chaos_batch=50)
    source = "SHAO 2018 (seed 000) Eqs. 18-26"
    improved = True

    def _improve(self, problem, rng, state):
        b = state["bulletin"]
        if len(b) <= self.stall:
            return
        gain = b[-1 - self.stall] - b[-1]
        X, Y = state["X"], state["Y"]
        if state["ban"] > 0:
            state["ban"] -= 1
        elif gain < self.eps:
            worst = np.argsort(Y)[-self.n_mutate:]
            Xm = np.clip(X[worst] + self.mutation_scale * rng.standard_normal(X[worst].shape),
                         0.0, 1.0)
            X[worst], Y[worst] = Xm, problem.evaluate(Xm)
            state["ban"] = self.ban
            state["n_mutations"] = state.get("n_mutations", 0) + 1
        if gain == 0.0:  # bulletin unchanged: chaotic search around the best fish
            ib = int(np.argmin(Y))
            xb, yb = X[ib].copy(), Y[ib]
            state["n_chaos"] = state.get("n_chaos", 0) + 1
            z = np.clip(xb, 1e-3, 1 - 1e-3) + 1e-6 * rng.random(xb.size)  # Eq. 24
            used = 0
            while used < self.max_chaos and not problem.exhausted:
                Z = chaotic_sequence(z, self.chaos_batch)  # Eq. 25, mu = 4
                z = Z[-1]
                C = np.clip(xb + self.visual * (2 * Z - 1), 0.0, 1.0)  # Eq. 26
                Yc = problem.evaluate(C)
                used += len(C)
                k = int(np.argmax(Yc < yb)) if np.any(Yc < yb) else -1
                if k >= 0:  # accept the first improvement and leave the chaotic loop
                    X[ib], Y[ib] = C[k], Yc[k]
                    break
            b[-1] = float(min(b[-1], np.min(Y)))


class FFOA(Algorithm):
    """Standard fruit-fly optimisation (Pan 2012; YU Eqs. 3-7), one (X, Y) axis pair per
    dimension: ``X_i = X_axis + R(2 rand - 1)``, ``S = 1/sqrt(X^2 + Y^2)`` is the candidate
    (clipped into the cube), the swarm flies to the best smell if it improves (vision)."""
    name = "ffoa"
    defaults = dict(pop_size=200, max_iter=1000, radius=0.5, axis_low=0.8, axis_high=2.0)
    source = "YU 2015 (seed 002) Eqs. 3-7; Pan, KBS 26 (2012) 69-74"
    n_axes = 2

    def start(self, problem, rng, u0):
        axes = rng.uniform(self.axis_low, self.axis_high, (self.n_axes, problem.dim))
        problem.evaluate(np.asarray(u0)[None, :])  # the initial guess is on the bulletin too
        return {"axes": axes, "best": np.inf, "iteration": 0}

    def _radius(self, state):
        return self.radius

    def _candidates(self, rng, state, D):
        r = self._radius(state)
        flies = state["axes"][None, :, :] + r * (2 * rng.random((self.pop_size, self.n_axes, D)) - 1)
        dist = np.sqrt(np.sum(flies ** 2, axis=1))
        S = 1.0 / np.maximum(dist, 1e-12)
        return flies, S

    def step(self, problem, rng, state):
        flies, S = self._candidates(rng, state, problem.dim)
        smell = problem.evaluate(np.clip(S, 0.0, 1.0))
        k = int(np.argmin(smell))
        if smell[k] < state["best"]:  # vision phase: fly to the best smell
            state["best"] = float(smell[k])
            state["axes"] = flies[k]
        state["iteration"] += 1
        return state


class IFFOA(FFOA):
    """Improved FFOA (YU, EQUATIONS B.4, REC-L): three axes (X, Y, Z), self-adaptive step
    ``omega = omega0 (1 - Nc/Niter)^p`` (p = 4) as flight radius, and the transfer factor
    ``theta = omega (0.5 - rand)`` added to ``S = 1/Dist`` so S can leave (0, inf). The
    omega schedule is pluggable (EQUATIONS B.4 is REC-L): ``"power"`` omega0 (1 - Nc/Niter)^p,
    ``"one_minus_power"`` omega0 (1 - (Nc/Niter)^p), ``"exp"`` omega0 exp(-p Nc/Niter)."""
    name = "iffoa"
    defaults = dict(FFOA.defaults, omega0=1.0, p=4, schedule="power")
    source = "YU 2015 (seed 002) Eqs. 8-10 (reconstructed)"
    n_axes = 3

    def _radius(self, state):
        r = min(state["iteration"] / self.max_iter, 1.0)
        if self.schedule == "power":  # Eq. 8a-b (default reconstruction)
            return self.omega0 * (1.0 - r) ** self.p
        if self.schedule == "one_minus_power":
            return self.omega0 * (1.0 - r ** self.p)
        if self.schedule == "exp":
            return self.omega0 * np.exp(-self.p * r)
        raise ValueError(f"schedule = {self.schedule!r}: use 'power', 'one_minus_power' or 'exp'")

    def _candidates(self, rng, state, D):
        flies, S = super()._candidates(rng, state, D)
        theta = self._radius(state) * (0.5 - rng.random(S.shape))  # Eq. 8c-d
        return flies, S + theta  # Eq. 10c


class ChaoticPSO(Algorithm):
    """Chaos particle swarm (seed 001): inertia-weighted PSO, Eq. (9), with random inertia
    ``w = 0.5 + rand/2`` (Eq. 10) and velocity clamp ``V_max``; each iteration the worst 25 %
    of the particles are replaced by chaotic disturbances of the global best,
    ``Z' = (1 - alpha) Z(g) + alpha Z(k)``, ``alpha = 1 - ((k-1)/k)^m`` (Eqs. 11-14)."""
    name = "chaotic_pso"
    defaults = dict(pop_size=40, max_iter=500, c1=2.0, c2=2.0, v_max=0.2, m=2, chaos_share=0.25)
    source = "seed 001 Eqs. 9-14 (Kennedy-Eberhart PSO, logistic chaos)"

    def start(self, problem, rng, u0):
        n, D = self.pop_size, problem.dim
        X = rng.random((n, D))
        X[0] = u0
        V = self.v_max * (2 * rng.random((n, D)) - 1)
        Y = problem.evaluate(X)
        g = int(np.argmin(Y))
        z = rng.uniform(0.01, 0.99, D)
        return {"X": X, "V": V, "P": X.copy(), "PY": Y.copy(), "G": X[g].copy(),
                "GY": float(Y[g]), "z": z, "iteration": 0}

    def step(self, problem, rng, state):
        X, V, P, PY, G = state["X"], state["V"], state["P"], state["PY"], state["G"]
        n, D = X.shape
        k = state["iteration"] + 1
        w = 0.5 + rng.random((n, 1)) / 2  # Eq. 10
        r1, r2 = rng.random((n, D)), rng.random((n, D))
        V = w * V + self.c1 * r1 * (P - X) + self.c2 * r2 * (G - X)  # Eq. 9
        speed = np.linalg.norm(V, axis=1, keepdims=True)
        V = np.where(speed > self.v_max, V * self.v_max / np.maximum(speed, 1e-300), V)
        X = np.clip(X + V, 0.0, 1.0)
        Y = problem.evaluate(X)
        # chaotic disturbance of the inferior quarter (Step 6)
        n_bad = max(1, int(round(self.chaos_share * n)))
        worst = np.argsort(Y)[-n_bad:]
        Zk = chaotic_sequence(state["z"], n_bad)  # Eq. 11
        state["z"] = Zk[-1]
        alpha = 1.0 - ((k - 1) / k) ** self.m  # Eq. 14
        Zp = (1 - alpha) * G[None, :] + alpha * Zk  # Eq. 13 (cube coords: Z(g) = G)
        X[worst] = Zp  # Eq. 12 with X_min = 0, X_max = 1
        V[worst] = self.v_max * (2 * rng.random((n_bad, D)) - 1)
        Y[worst] = problem.evaluate(Zp)
        better = Y < PY
        P[better], PY[better] = X[better], Y[better]
        g = int(np.argmin(PY))
        if PY[g] < state["GY"]:
            state["G"], state["GY"] = P[g].copy(), float(PY[g])
        state.update(X=X, V=V, P=P, PY=PY, iteration=k)
        return state


ALGORITHM_CLASSES = (AFSA, IAFSA, FFOA, IFFOA, ChaoticPSO)
