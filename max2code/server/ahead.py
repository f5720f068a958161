"""A held body's segment fitted to the ticks ahead: a shadow copy of the room's world.

A body the contact solver holds is sent as a chord, quadratic or cubic (reckon.py) and re-sent
when the truth would leave the held bound. Fitted to the body's past ticks, such a segment
lasts 3-5 ticks while a box tips (its error grows as the jerk's s^3 from the fit's window on);
fitted to the ticks ahead it would last 15-30 (bench/held_life.py). The engine is deterministic
and a World copies bit for bit (docs/engine-contact.md, "Snapshots"), so the room keeps a copy
of its world (`Shadow`) stepped LOOKAHEAD ticks ahead of its clock, recording each held body's
motion at every solver tick, and when it must (re)send a held body it fits its forms to those
motions (`forecast`) and measures every candidate's life against them (`life`).

The forecast is only advice: the room still checks what clients hold against the truth at
every tick and re-sends when it would leave the bound, so a wrong forecast (an input the copy
did not get) costs bytes, never exactness. The room drops the copy when it edits its world
(input) and when a tick's truth differs from the copy's record, and makes a new one.
A world with Python callbacks (a game's) is never copied: its callbacks must not run twice.
"""

from __future__ import annotations

import copy
import math

from ..engine.world import World
from . import reckon
from .reckon import Motion, state_at

LOOKAHEAD = 48      # solver ticks the copy runs ahead (0.2 s at 240 Hz): a tipping box's cubic
                    # fitted ahead lasts some 30 (bench/held_life.py)
MARGIN = 0.95       # of the bound: what a forecast candidate may use (the rest: rounding, and
                    # the flight between the instants checked)
TRIES = 4           # windows tried per degree, besides the first two
FIRST = 12          # samples in the first window (4 ticks: the rate's interval at 60 a second)


class Shadow:
    """A copy of a world stepped ahead of it, recording each body the solver holds: its motion
    as the core gives it at every solver tick (a break, None, where the solver let it go)."""

    def __init__(self, world: World, step: float, ticks: int = LOOKAHEAD) -> None:
        self.world = copy.deepcopy(world)
        self.step = step
        self.horizon = ticks * step
        self.flights: dict[int, list[Motion | None]] = {}
        self.counters: list[int] = []

    @staticmethod
    def possible(world: object) -> bool:
        """Whether a room's world may be copied to look ahead: an engine World with the
        contact solver on and no Python callbacks (a game's would run twice)."""
        return (isinstance(world, World) and getattr(world, "contact_step", 0.0) > 0
                and not world.has_callbacks())

    def run_to(self, now: float) -> None:
        """Step the copy until it is the horizon ahead of `now`, one solver tick at a time (to
        the middle of each tick: the tick is done, the next is not), recording the held bodies,
        and forget what lies before `now`."""
        w, h = self.world, self.step
        end = now + self.horizon
        while w.time < end:
            w.step_to(reckon.next_tick(w.time, h) + h / 2, events=False)
            motions, counters = w.motions()
            old = self.counters + [-1] * (len(counters) - len(self.counters))
            for i, (m, c, was) in enumerate(zip(motions, counters, old)):
                fl = self.flights.get(i)
                if c == was and not fl:
                    continue    # (the solver changes what it holds at every tick)
                if c != was and w.solving(i):
                    if fl is None:
                        self.flights[i] = [m]
                    elif fl[-1] is None or fl[-1][0] < m[0]:
                        fl.append(m)
                elif fl and fl[-1] is not None:
                    fl.append(None)
            self.counters = counters
        for i, fl in list(self.flights.items()):
            k = 0           # (keep the motion in force at `now`)
            while k + 1 < len(fl) and (fl[k + 1] is None or fl[k + 1][0] <= now):
                k += 1
            del fl[:k]
            if fl == [None]:
                del self.flights[i]

    def agrees(self, i: int, m: Motion) -> bool:
        """False when the copy recorded body i with a motion from m's time that is not m (it
        went another way: an edit it did not get); True otherwise (also when it has none)."""
        for f in self.flights.get(i, ()):
            if f is not None and f[0] == m[0]:
                return tuple(f) == tuple(m)
        return True

    def ahead(self, i: int, now: float) -> list[Motion]:
        """Body i's recorded motions after `now`, while the solver keeps holding it."""
        out = []
        for f in self.flights.get(i, ()):
            if f is None:
                break
            if f[0] > now:
                out.append(f)
        return out


class Ahead:
    """A held body's path from t as the copy recorded it (the truth now, then its motion at
    each tick ahead), sampled at the start, middle and end of each motion (the flight between
    two ticks is a parabola, a candidate a low polynomial): each sample's time from t (`s`)
    and its pose less the pose at t (`d`, the angle wrapped; evaluated as far as asked: a
    jittering body's candidates fail within a tick or two). Every candidate starts at the
    pose at t."""

    def __init__(self, truth: Motion, flights: list[Motion], t: float, bound: float,
                 reach: float, h: float) -> None:
        self.t, self.h = t, h
        self.bound = bound      # along x and y, and through rotation at `reach`
        self.reach = reach
        self.now = state_at(truth, t)[:3]
        path = [truth] + flights
        self._at: list[tuple[float, Motion]] = []
        for k, f in enumerate(path):
            start = max(f[0], t)
            stop = path[k + 1][0] if k + 1 < len(path) else f[0] + h
            if stop > start:
                self._at += [(u, f) for u in (start, (start + stop) / 2, stop) if u > t]
        self.s = [u - t for u, _ in self._at]
        self.d: list[tuple[float, float, float]] = []

    def poses(self, n: int) -> list[tuple[float, float, float]]:
        """`d` evaluated for at least the first n samples (a dozen more at a time)."""
        x0, y0, a0 = self.now
        for u, f in self._at[len(self.d):max(n, len(self.d) + 12)]:
            p = state_at(f, u)
            turn = p[2] - a0
            self.d.append((p[0] - x0, p[1] - y0, turn - 2 * math.pi * round(turn / (2 * math.pi))))
        return self.d

    @property
    def end(self) -> float:
        return self.s[-1] if self.s else 0.0

    def life(self, m: Motion) -> float:
        """How long from t the segment m (from t) stays within MARGIN x bound of the path,
        along x and y and through rotation at `reach`, at the samples (at most the path's end)."""
        if m[0] != self.t:
            raise ValueError("a candidate starts at the path's time")
        vx, vy, w, ax, ay, al, jx, jy, ja = (tuple(m[4:13]) + (0.0,) * 9)[:9]
        e, r = MARGIN * self.bound, self.reach
        ok = 0.0
        for k, s in enumerate(self.s):
            dx, dy, da = (self.d if k < len(self.d) else self.poses(k + 1))[k]
            if (abs(s * (vx + s * (0.5 * ax + jx * s / 6)) - dx) > e
                    or abs(s * (vy + s * (0.5 * ay + jy * s / 6)) - dy) > e
                    or r * abs(s * (w + s * (0.5 * al + ja * s / 6)) - da) > e):
                return ok
            ok = s
        return ok

    def forecast(self, upto: int = 3) -> list[tuple[Motion, float]]:
        """Segments from t (through the pose at t) fitted to the path, each with its life:
        for each degree up to `upto` (1: a straight line, 2: quadratic, 3: cubic; per x, y and
        the angle), least squares over the samples of a window from t, the window doubled
        from 4 ticks while the fit lasts it, then halved back once (a lower degree that lasts
        the whole path ends the search: a higher one costs more bytes)."""
        if not self.s:
            return []
        h, reach, bound = self.h, self.reach, self.bound
        # prefix sums of u^p (p = 0..6) and u^k d (k = 0..3), u = s / h, as far as needed
        mom: list[tuple[float, ...]] = []
        rhs: list[tuple[tuple[float, float, float], ...]] = []

        def sums(n: int) -> None:
            sm = mom[-1] if mom else (0.0,) * 7
            sr = rhs[-1] if rhs else ((0.0, 0.0, 0.0),) * 4
            for s, (dx, dy, da) in zip(self.s[len(mom):n], self.poses(n)[len(mom):n]):
                u = s / h
                u2 = u * u
                pw = (1.0, u, u2, u2 * u, u2 * u2, u2 * u2 * u, u2 * u2 * u2)
                sm = tuple(a + b for a, b in zip(sm, pw))
                sr = tuple((r[0] + p * dx, r[1] + p * dy, r[2] + p * da) for r, p in zip(sr, pw))
                mom.append(sm)
                rhs.append(sr)

        def fit(degree: int, n: int) -> Motion | None:
            """The fit over the first n samples, its accelerations and jerks shortened."""
            sums(n)
            scale = self.s[n - 1] / h
            m = [[mom[n - 1][p + q] / scale ** (p + q) for q in range(1, degree + 1)]
                 + [rhs[n - 1][p][c] / scale ** p for c in range(3)] for p in range(1, degree + 1)]
            sol = reckon.solve(m)
            if sol is None:
                return None
            span = scale * h        # (c_k (u / scale)^k = c_k / span^k s^k: v, a/2, j/6)
            out = []
            for c, r in zip(range(3), (1.0, 1.0, reach if reach > 0 else 1.0)):
                k = [sol[q][c] / span ** (q + 1) * math.factorial(q + 1) for q in range(degree)]
                k += [0.0] * (3 - degree)
                # accelerations and jerks with the fewest digits that move it by at most 1/16
                # of the bound over the window (reckon.fitted's rule)
                out.append((k[0], reckon._short(k[1], bound / (8 * span * span * r)),
                            reckon._short(k[2], 3 * bound / (8 * span ** 3 * r))))
            (vx, ax, jx), (vy, ay, jy), (w, al, ja) = out
            full = (self.t, *self.now, vx, vy, w, ax, ay, al, jx, jy, ja)
            return full[:9] if degree == 1 else full[:10] if degree == 2 else full

        out = []
        for degree in range(1, upto + 1):
            best, good, bad, n = None, 0, len(self.s) + 1, min(len(self.s), FIRST)
            for _ in range(TRIES + 2):
                m = fit(degree, n) if n >= degree else None
                if m is None:
                    break
                lasts = self.life(m)
                if best is None or lasts > best[1]:
                    best = (m, lasts)
                if lasts >= self.s[n - 1]:
                    good = n
                else:
                    bad = n
                if good == len(self.s) or bad - good <= 1 + len(self.s) // 16:
                    break
                n = min(2 * n, len(self.s)) if bad > len(self.s) else (good + bad) // 2
            if best is not None:
                out.append(best)
                if best[1] >= self.end:
                    break
        return out

