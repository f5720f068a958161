#!/usr/bin/env python3
"""Our predictive engine against the frame-based engines people use: pymunk (Chipmunk2D) and Box2D.

    python bench/engine.py            # everything, ~3 minutes on 2 shared cores
    python bench/engine.py --quick    # fewer trials and shorter runs (for trying things out)

Needs the bench extra (pip install -e '.[bench]': pymunk 7.3.1, Box2D 2.3.10, numpy,
matplotlib). Every measure runs, in one run, for pymunk and Box2D at dt = 1/60 and 1/240 and for
our engine (bench/engine_ours.py; its column says "not run" and why when max2code.engine is not
there). The scenes are bench/engine_scenes.py: the same bodies for every engine; what an engine
cannot model exactly is listed in bench/engine_anchors.py and in the results.

Measures:
  tunnel     a ball of radius 0.01 against a thin wall: tunnelled of 200, at 1 .. 1000 m/s
  contact    two discs on a collision course: |reported - exact| first contact time (50 pairs)
  rotation   a spinning square against a wall: the same against the exact trigonometric motion
  energy     20 elastic discs in a box with gravity, 60 s: |E(t) - E(0)| / E(0)
  cost       wall seconds per simulated second, gases of N = 10 / 100 / 1000 discs, sparse and
             dense (engine_scenes.GAS), best of 3 runs; and contacts per simulated second
  idle       wall seconds per simulated second when nothing collides (100 drifting discs)
  stacking   sustained contact (bench/engine_stacking.py): a box dropped on its corner, a column
             of 10 boxes standing and jittered, a pyramid of 10, 200 discs collapsing (e 0.8):
             final tilt, toppled, drift, worst overlap, energy, wall time

Writes bench/results/engine.md (table), engine.json (all figures) and one chart per measure,
bench/results/engine_<measure>.png. Wall times are noisy on a shared machine: compare the engines
within one run (they run interleaved), not across runs.
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import platform
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import engine_anchors  # noqa: E402
import engine_ours  # noqa: E402
import engine_stacking  # noqa: E402
import engine_scenes as S  # noqa: E402
from roots import machine  # noqa: E402
from benchtools import results_dir, smoke  # noqa: E402

RESULTS = results_dir(HERE / "results")
SIZES = (10, 100, 1000)
KINDS = ("sparse", "dense")


def engines(quick: bool) -> tuple[list, dict]:
    """The engines to run, and why any was left out."""
    out = list(engine_anchors.anchors())
    skipped = {}
    reason = engine_ours.unavailable()
    if reason is None:
        out.append(engine_ours.Ours())
        print(f"bench/engine: ours is max2code.engine from {engine_ours.version()}", flush=True)
    else:
        skipped["ours"] = reason
    return out, skipped


# --- the measures ------------------------------------------------------------------------------

def tunnel(engine, quick: bool) -> dict:
    trials = 40 if quick else 200
    out = {}
    for speed in S.TUNNEL_SPEEDS:
        count = 0
        for scene, t_end in S.tunnel_trials(speed, trials):
            sim = engine.build(scene)
            sim.advance(t_end)
            count += S.tunnelled(sim.states()[0][0])
        out[str(speed)] = count
    return {"trials": trials, "tunnelled": out}


def contact_errors(engine, trials, pair=(0, 1)) -> dict:
    """|first reported contact of the pair - exact| over the trials (a missed contact: inf)."""
    errors, relative = [], []
    for scene, exact in trials:
        sim = engine.build(scene, record=True)
        sim.advance(exact + 0.25)
        times = [t for t, i, j in sim.contacts if (i, j) == pair]
        err = abs(times[0] - exact) if times else math.inf
        errors.append(err)
        relative.append(err / exact)
    finite = [e for e in errors if math.isfinite(e)]
    return {"median": statistics.median(errors), "max": max(errors), "max_relative": max(relative),
            "missed": len(errors) - len(finite), "errors": errors}


def energy(engine, quick: bool) -> dict:
    scene = S.energy_box()
    sim = engine.build(scene)
    e0 = S.energy(scene, sim.states())
    seconds = 10 if quick else 60
    series = []
    for t in range(1, seconds + 1):
        sim.advance(float(t))
        series.append(abs(S.energy(scene, sim.states()) - e0) / e0)
    return {"seconds": seconds, "final": series[-1], "max": max(series), "series": series}


FPS = 60


def timed(engine, scene, seconds: float, repeats: int, frames: bool = False) -> float:
    """Best (least disturbed) wall time per simulated second over `repeats` fresh runs. With
    `frames`, the run stops every 1/60 s of simulated time and reads every body's pose (a game
    loop's frames), in every engine alike."""
    best = math.inf
    for _ in range(repeats):
        sim = engine.build(scene)
        start = time.perf_counter()
        if frames:
            for k in range(1, int(round(seconds * FPS)) + 1):
                sim.advance(k / FPS)
                sim.poses()
        else:
            sim.advance(seconds)
        best = min(best, time.perf_counter() - start)
    return best / seconds


def sim_seconds(n: int, quick: bool) -> float:
    return {10: 20.0, 100: 10.0, 1000: 3.0}[n] / (4 if quick else 1)


def cost(engine, quick: bool) -> dict:
    out = {}
    repeats = 1 if quick else 3
    for kind in KINDS:
        for n in SIZES:
            scene = S.gas(n, kind)
            seconds = sim_seconds(n, quick)
            wall = timed(engine, scene, seconds, repeats)
            sim = engine.build(scene, record=True)
            sim.advance(seconds)
            events = getattr(sim, "events", None)
            out[f"{kind} {n}"] = {
                "wall_per_sim_s": wall,
                "wall_per_sim_s_frames": timed(engine, scene, seconds, repeats, frames=True),
                "contacts_per_s": len(sim.contacts) / seconds,
                "events_per_s": events / seconds if events is not None else None,
                "us_per_event": 1e6 * wall * seconds / events if events else None}
    return out


def idle(engine, quick: bool) -> dict:
    scene = S.idle(100)
    seconds = 5.0 if quick else 20.0
    repeats = 1 if quick else 3
    sim = engine.build(scene, record=True)
    sim.advance(seconds)
    return {"n": 100, "contacts": len(sim.contacts),
            "wall_per_sim_s": timed(engine, scene, seconds, repeats),
            "wall_per_sim_s_frames": timed(engine, scene, seconds, repeats, frames=True)}


MEASURES = ("tunnel", "contact", "rotation", "energy", "cost", "idle", "stacking")


def run(quick: bool) -> dict:
    chosen, skipped = engines(quick)
    two = S.two_disc_trials(15 if quick else 50)
    spin = S.square_wall_trials(10 if quick else 30)
    results = {"date": datetime.date.today().isoformat(), "machine": machine(),
               "python": platform.python_version(), "versions": engine_anchors.versions(),
               "quick": quick, "skipped": skipped, "engines": [e.label for e in chosen], "by": {},
               "ours": engine_ours.version() if "ours" not in skipped else None}
    for engine in chosen:
        start = time.perf_counter()
        r = results["by"][engine.label] = {}
        for name, measure in (("tunnel", lambda: tunnel(engine, quick)),
                              ("contact", lambda: contact_errors(engine, two)),
                              ("rotation", lambda: contact_errors(engine, spin, pair=(-1, 0))),
                              ("energy", lambda: energy(engine, quick)),
                              ("cost", lambda: cost(engine, quick)),
                              ("idle", lambda: idle(engine, quick)),
                              ("stacking", lambda: engine_stacking.stacking(engine, quick))):
            try:
                r[name] = measure()
            except Exception as exc:  # an engine that cannot run a scene: said, not hidden
                r[name] = {"error": f"{type(exc).__name__}: {exc}".splitlines()[0]}
                print(f"bench/engine: {engine.label} {name}: {r[name]['error']}", flush=True)
        print(f"bench/engine: {engine.label} done in {time.perf_counter() - start:.0f} s", flush=True)
    return results


# --- output ------------------------------------------------------------------------------------

def _e(x) -> str:
    if x is None:
        return "–"
    if isinstance(x, float) and math.isinf(x):
        return "missed"
    return "0" if x == 0 else f"{x:.1e}"


def _t(x) -> str:
    """Wall seconds, to two significant digits."""
    return "–" if x is None else f"{x:.2g}"


def _per_n(r: dict, kind: str, key: str, fmt) -> str:
    cells = []
    for n in SIZES:
        v = r["cost"][f"{kind} {n}"].get(key)
        cells.append("–" if v is None else fmt(v))
    return " / ".join(cells)


def _rows(trials: int) -> list[tuple[str, str, object]]:
    """(row name, measure, cell of one engine's results)."""
    speeds = " / ".join(f"{s:g}" for s in S.TUNNEL_SPEEDS)
    rows = [
        (f"tunnelled of {trials}, r 0.01 at 100 m/s", "tunnel",
         lambda r: str(r["tunnel"]["tunnelled"]["100.0"])),
        (f"tunnelled of {trials} at {speeds} m/s", "tunnel",
         lambda r: " / ".join(str(r["tunnel"]["tunnelled"][str(s)]) for s in S.TUNNEL_SPEEDS)),
        ("contact time error, two discs: median / max (s)", "contact",
         lambda r: f"{_e(r['contact']['median'])} / {_e(r['contact']['max'])}"),
        ("contact time error, two discs: max relative", "contact",
         lambda r: _e(r["contact"]["max_relative"])),
        ("contact time error, spinning square (rotation): median / max (s)", "rotation",
         lambda r: f"{_e(r['rotation']['median'])} / {_e(r['rotation']['max'])}"),
        ("energy drift, 20 discs, gravity, 60 s: final / max", "energy",
         lambda r: f"{_e(r['energy']['final'])} / {_e(r['energy']['max'])}"),
    ]
    for kind in KINDS:
        rows.append((f"wall s per simulated s, {kind}, N = 10 / 100 / 1000", "cost",
                     lambda r, k=kind: _per_n(r, k, "wall_per_sim_s", _t)))
    for kind in KINDS:
        rows.append((f"the same with 60 frames/s (every pose read each frame), {kind}", "cost",
                     lambda r, k=kind: _per_n(r, k, "wall_per_sim_s_frames", _t)))
    for kind in KINDS:
        rows.append((f"contacts per simulated s, {kind}", "cost",
                     lambda r, k=kind: _per_n(r, k, "contacts_per_s", lambda v: f"{v:.0f}")))
    for kind in KINDS:
        rows.append((f"events per simulated s, {kind} (all kinds: contacts, cell crossings, ...)", "cost",
                     lambda r, k=kind: _per_n(r, k, "events_per_s", lambda v: f"{v:.0f}")))
    for kind in KINDS:
        rows.append((f"µs per event, {kind} (events only)", "cost",
                     lambda r, k=kind: _per_n(r, k, "us_per_event", lambda v: f"{v:.1f}")))
    rows.append(("idle scene (100 discs, no contact): wall s per simulated s", "idle",
                 lambda r: _t(r["idle"]["wall_per_sim_s"])))
    rows.append(("idle scene with 60 frames/s (every pose read each frame)", "idle",
                 lambda r: _t(r["idle"]["wall_per_sim_s_frames"])))
    return rows


def table(results: dict) -> str:
    by = results["by"]
    cols = results["engines"] + sorted(results["skipped"])
    lines = [f"| measure | {' | '.join(cols)} |", "|---" * (len(cols) + 1) + "|"]
    for name, measure, cell in _rows(40 if results["quick"] else 200):
        cells = []
        for label in cols:
            if label not in by:
                cells.append("not run")
            elif "error" in by[label][measure]:
                cells.append("failed *")
            else:
                cells.append(cell(by[label]))
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def failures(results: dict) -> list[str]:
    return [f"{label}, {measure}: {r['error']}" for label, rs in results["by"].items()
            for measure, r in rs.items() if "error" in r]


def markdown(results: dict) -> str:
    v = results["versions"]
    head = [
        "# Predictive engine against frame-based engines",
        "",
        f"`python bench/engine.py`{' --quick' if results['quick'] else ''} on {results['date']}: "
        f"{results['machine']}, Python {results['python']}, pymunk {v['pymunk']} (Chipmunk "
        f"{v['chipmunk']}), Box2D {v['Box2D']}. Every engine in one run; wall times are the best of "
        "3 runs on a machine shared with other work: compare the columns, not runs.",
        "",
        table(results),
        "",
    ]
    for name, why in results["skipped"].items():
        head += [f"Not run: **{name}**: {why}.", ""]
    for line in failures(results):
        head += [f"\\* failed: {line}", ""]
    ran = [label for label in results["engines"] if "stacking" in results["by"][label]]
    if ran:
        head += ["## Sustained contact: stacks, a tilted drop, a dense collapse", "",
                 *engine_stacking.table(results["by"], ran), "",
                 "Scenes and measures: bench/engine_stacking.py. Boxes are 0.5 m, 1 kg, on a floor "
                 "segment; friction 0.5 (the tilted drop's last row 0) and restitution 0 (one drop "
                 "0.5) for every contact; the discs are bench/contact.py's (r 0.15 m, e 0.8, no "
                 "friction, a 10 m bin). Every engine as used for stacking: sleeping allowed, "
                 "pymunk's collision slop 5 mm, ours with its contact solver "
                 f"(contact_step {engine_ours.contact_step():.3g} s). Overlap is measured on the "
                 "states every 0.5 s and at the end by separating axes (Box2D keeps polygons "
                 "about 0.01 m apart by its skin: its height and drift include it). Wall: each "
                 "engine's stepping alone, one run.", ""]
    head += [
        f"Ours: max2code.engine's World (from {results['ours']}) with tolerance 1e-9 on contact "
        "times (bench/engine_ours.py). "
        "Scenes (bench/engine_scenes.py, the same bodies in every engine, friction 0, e = 1):",
        "",
        "* tunnel: a disc of radius 0.01 m, 0.01 kg, at 1 .. 1000 m/s along +x at a wall x = 0 "
        "(a segment of zero thickness), 200 starts spread over one frame of travel; tunnelled = "
        "past the wall when an unhindered ball would be 1 m beyond it.",
        "* contact: discs of radius 0.3 and 0.5 (1 and 2 kg) meeting after 0.5..1.5 s at 1..4 m/s "
        "relative speed, impact parameter up to 0.8 of the radius sum; exact time: the quadratic's "
        "root. Reported time: the time of the state in which the engine finds the contact "
        "(pymunk: end of the step; Box2D: start of the step, or its end for a time-of-impact "
        "contact).",
        "* rotation: a square of half side 0.25 m (1 kg) at 0.5..3 m/s spinning at 2..12 rad/s "
        "towards a wall; exact time on the trigonometric motion (conservative advancement and "
        "bisection in mpmath, 40 digits).",
        "* energy: 20 discs (r 0.3 m, 1 kg) at 2..6 m/s in a 10 m box, gravity 9.81; potential "
        "energy zero at the floor; sampled every simulated second.",
        "* cost: a gas of discs (r 1 m, 1 kg) scattered uniformly in a square box, no gravity; "
        "sparse: area fraction 0.02 at 4 m/s, dense: 0.25 at 5.5 m/s (the contact rates of "
        "DESIGN.md §8, calibrated with pymunk at 1/240). Contacts: new touching pairs (disc-disc "
        "and disc-wall) per simulated second; ours: collision events.",
        "* idle: 100 discs (r 1 m) 8 m apart drifting at 0.01 m/s: no contact.",
        "* frames: the cost and idle runs are timed twice: stepping alone (the anchors' steps, "
        "our events), and stopping every 1/60 s of simulated time to read every body's pose, "
        "as a game loop draws (pymunk and Box2D: their bodies' attributes; ours: World.poses). "
        "That row is mostly the cost of each Python binding's pose reading (pymunk's Vec2d "
        "attributes cost several µs a body), not of the engines' physics.",
        "",
        "What the anchors cannot model exactly: Box2D gives polygons and edges a skin of 0.01 m "
        "(a disc or a square touches a wall 0.01 m early: most of its error in the rotation row is "
        "early contacts), ignores restitution below 1 m/s closing speed (inelastic then: part of its energy "
        "drift), and moves no body more than 2 m in a step (at 1/60 it caps speed at 120 m/s). "
        "pymunk detects contacts at the step's positions only (no continuous collision).",
        "",
    ]
    return "\n".join(head)


def charts(results: dict) -> list[Path]:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    by, labels = results["by"], results["engines"]
    # distinct hues and markers per engine (shades of one colour per library could not be told
    # apart with 10 lines on a chart)
    colours = {"pymunk 1/60": "#1f77b4", "pymunk 1/240": "#17becf", "Box2D 1/60": "#d62728",
               "Box2D 1/240": "#ff7f0e", "ours": "#2ca02c"}
    markers = {"pymunk 1/60": "o", "pymunk 1/240": "^", "Box2D 1/60": "s", "Box2D 1/240": "D",
               "ours": "*"}
    made = f"{results.get('machine', 'machine not recorded')}, {results.get('date', '')}"
    written = []

    def ran(measure: str) -> list[str]:
        return [label for label in labels if "error" not in by[label][measure]]

    def save(fig, name: str, measure: str, note: str = "") -> None:
        """Writes the chart with the machine and date at the top right; `note`, a caption
        under the plot."""
        failed = [label for label in labels if "error" in by[label][measure]]
        if note:
            fig.text(0.01, 0.01, note, fontsize=7.5, va="bottom")
        if failed:   # say who is missing and why, on the chart itself
            fig.text(0.01, 0.005, "not shown: " + "; ".join(
                f"{label} (failed: {by[label][measure]['error'][:100]})" for label in failed), fontsize=7)
        fig.text(0.99, 0.995, made, fontsize=8, color="#555", ha="right", va="top")
        path = RESULTS / f"engine_{name}.png"
        fig.tight_layout(rect=(0, (0.03 if failed else 0) + (0.09 if note else 0), 1, 0.97))
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)

    # tunnel: tunnelled against speed
    fig, ax = plt.subplots(figsize=(6.4, 4))
    speeds = list(S.TUNNEL_SPEEDS)
    for k, label in enumerate(ran("tunnel")):
        counts = [by[label]["tunnel"]["tunnelled"][str(s)] for s in speeds]
        ax.plot(speeds, counts, "o-", color=colours.get(label), label=label, alpha=0.9,
                markersize=6 - k * 0.6)
    ax.set_xscale("log")
    ax.set_xlabel("ball speed (m/s), radius 0.01 m")
    ax.set_ylabel(f"tunnelled of {40 if results['quick'] else 200}")
    ax.set_title("Thin wall: balls that went through")
    ax.legend()
    ax.grid(alpha=0.3)
    save(fig, "tunnel", "tunnel")

    # contact time and rotation: error distributions
    for measure, title in (("contact", "Two discs: first contact time error"),
                           ("rotation", "Spinning square against a wall: contact time error")):
        fig, ax = plt.subplots(figsize=(6.4, 4))
        shown = ran(measure)
        data = [[max(e, 1e-17) for e in by[label][measure]["errors"] if math.isfinite(e)] for label in shown]
        ax.boxplot(data, whis=(0, 100))
        ax.set_xticks(range(1, len(shown) + 1), shown)
        ax.set_yscale("log")
        ax.set_ylabel("|reported - exact| (s); 0 drawn at 1e-17")
        ax.set_title(title)
        ax.grid(alpha=0.3, axis="y")
        save(fig, measure, measure)

    # energy: drift over time
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for label in ran("energy"):
        series = by[label]["energy"]["series"]
        ax.plot(range(1, len(series) + 1), [max(s, 1e-17) for s in series], color=colours.get(label), label=label)
    ax.set_yscale("log")
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("|E(t) - E(0)| / E(0); 0 drawn at 1e-17")
    ax.set_title("20 elastic discs in a box with gravity: energy drift")
    ax.legend()
    ax.grid(alpha=0.3)
    # (said on the chart: read alone, Box2D's line looks like integration error)
    box2d = any(label.startswith("Box2D") for label in ran("energy"))
    save(fig, "energy", "energy", note="Box2D: most of its drift is its restitution threshold "
         "(b2_velocityThreshold = 1 m/s):\nslower impacts are made perfectly inelastic, and "
         "discs bouncing under gravity make many of them." if box2d else "")

    def per_n(name: str, title: str, ylabel: str, series, legend_size: float = 10) -> None:
        """Two log-log panels (sparse, dense) against N; series(label, kind) gives
        (values, line style, legend) lines, values None where there are none. Each engine its
        own colour and marker, each line labelled at its right end too."""
        fig, axes = plt.subplots(1, 2, figsize=(14, 5.2), sharey=True)
        fig.suptitle(title, fontsize=12)
        for ax, kind in zip(axes, KINDS):
            ends = []
            for label in ran("cost"):
                for values, style, legend in series(label, kind):
                    if all(v is not None for v in values):
                        ax.plot(SIZES, values, style, color=colours.get(label), label=legend,
                                marker=markers.get(label, "o"), markersize=5,
                                markerfacecolor="white" if style != "-" else colours.get(label))
                        ends.append((values[-1], legend, colours.get(label)))
            # labels at the lines' ends, spread apart (at least a factor `gap`) where lines meet
            gap, placed = 1.45, []
            for value, legend, colour in sorted(ends):
                y = max(value, placed[-1] * gap) if placed else value
                placed.append(y)
                ax.annotate(legend, (SIZES[-1], value), xytext=(SIZES[-1] * 1.5, y), fontsize=7,
                            va="center", color=colour, arrowprops={"arrowstyle": "-", "color": colour,
                                                                  "lw": 0.5})
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(SIZES[0] / 1.3, SIZES[-1] * 12)   # room for the labels at the lines' ends
            ax.set_xlabel("N discs")
            ax.set_title(f"{kind} gas")
            ax.grid(alpha=0.3)
        axes[0].set_ylabel(ylabel)
        # Beside the panels, not over them: the lines cross every corner of the plots.
        axes[1].legend(fontsize=legend_size, loc="upper left", bbox_to_anchor=(1.02, 1))
        axes[0].set_ylim(top=axes[0].get_ylim()[1] * 4)
        save(fig, name, "cost")

    def cost_of(label: str, kind: str, key: str) -> list:
        return [by[label]["cost"][f"{kind} {n}"].get(key) for n in SIZES]

    per_n("cost", "Gas of N discs: wall time per simulated second (solid: stepping alone, "
          "dotted, hollow: with 60 frames/s read)", "wall s per simulated s", lambda label, kind: [
        (cost_of(label, kind, "wall_per_sim_s"), "-", label),
        (cost_of(label, kind, "wall_per_sim_s_frames"), ":", f"{label}, 60 frames/s")], legend_size=7)
    per_n("events", "Gas of N discs: contacts and events per simulated second",
          "per simulated second", lambda label, kind: [
        (cost_of(label, kind, "contacts_per_s"), "-", f"{label}: contacts"),
        (cost_of(label, kind, "events_per_s"), "--", f"{label}: all events")], legend_size=8)

    # idle
    fig, ax = plt.subplots(figsize=(6.4, 4))
    shown = ran("idle")
    xs = range(len(shown))
    ax.bar([x - 0.2 for x in xs], [by[label]["idle"]["wall_per_sim_s"] for label in shown], width=0.4,
           color=[colours.get(label) for label in shown], label="stepping alone")
    ax.bar([x + 0.2 for x in xs], [by[label]["idle"]["wall_per_sim_s_frames"] for label in shown], width=0.4,
           color=[colours.get(label) for label in shown], hatch="//", edgecolor="white",
           label="with 60 frames/s (poses read)")
    ax.set_xticks(list(xs), shown)
    ax.legend()
    ax.set_yscale("log")
    ax.set_ylabel("wall s per simulated s")
    ax.set_title("Idle scene: 100 discs, nothing collides")
    ax.grid(alpha=0.3, axis="y")
    save(fig, "idle", "idle")
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer trials, shorter runs")
    parser.add_argument("--charts-only", action="store_true",
                        help="redraw the charts from bench/results/engine.json, run nothing")
    args = parser.parse_args(argv)
    if args.charts_only:
        for path in charts(json.loads((RESULTS / "engine.json").read_text())):
            print(f"bench/engine: wrote {path}")
        return 0
    results = run(args.quick or smoke())
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "engine.json").write_text(json.dumps(results, indent=1) + "\n")
    (RESULTS / "engine.md").write_text(markdown(results))
    for path in charts(results):
        print(f"bench/engine: wrote {path}")
    print(table(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
