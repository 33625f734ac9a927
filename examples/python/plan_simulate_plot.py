#!/usr/bin/env python3
"""Plan a world, simulate the plan, print the verdicts and plot what the simulation did.

    PYTHONPATH=build/python python3 examples/python/plan_simulate_plot.py [WORLD] [-o FIGURE.png]

The figure: each robot's TCP height and each object's height over plan time, with the
planned actions shaded and the failed ones in red.
"""

import argparse
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dashbed  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("world", nargs="?", help="world file (default: the built-in default world)")
    parser.add_argument("-o", "--output", default="run.png", help="where to save the figure (PNG)")
    parser.add_argument("--method", default="greedy", choices=["greedy", "optimal"])
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    world = dashbed.World.load(args.world) if args.world else dashbed.World.default()
    result = dashbed.plan(world, method=args.method, seed=args.seed)
    if not result.solved:
        print(f"{world.name}: {result.status}: {result.reason}", file=sys.stderr)
        return 4
    plan = result.plan
    print(f"{world.name}: planned {len(plan.actions)} actions, makespan {plan.duration:.2f} s "
          f"in {sum(result.statistics['seconds'].values()):.2f} s")

    report = dashbed.simulate(world, plan, samples=50.0)
    print(report.text(), end="")

    s = report.samples
    t = s["times"]
    tcp = s["links"].index("tcp")
    fig, (ax_robots, ax_objects) = plt.subplots(2, 1, sharex=True, figsize=(10, 6))
    for r, name in enumerate(s["robots"]):
        ax_robots.plot(t, s["link_poses"][:, r, tcp, 2], label=name)
    for o, name in enumerate(s["objects"]):
        ax_objects.plot(t, s["object_poses"][:, o, 2], label=name)
    for action in report.actions:
        colour = "tab:green" if action.passed else "tab:red"
        for ax in (ax_robots, ax_objects):
            ax.axvspan(action.planned_start, action.planned_end, color=colour, alpha=0.08)
    ax_robots.set_ylabel("TCP height [m]")
    ax_objects.set_ylabel("object height [m]")
    ax_objects.set_xlabel("plan time [s]")
    ax_robots.legend(loc="upper right", fontsize="small")
    ax_objects.legend(loc="upper right", fontsize="small", ncol=max(1, len(s["objects"]) // 8))
    verdict = "PASSED" if report.passed else "FAILED"
    ax_robots.set_title(f"{world.name}: {verdict}, {report.summary['passed']} of {len(report.actions)} actions")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output} ({len(t)} samples, highest object {np.max(s['object_poses'][:, :, 2]):.3f} m)")
    return 0 if report.passed else 1


if __name__ == "__main__":
    sys.exit(main())
