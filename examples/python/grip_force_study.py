#!/usr/bin/env python3
"""A small parameter study: the success rate of a plan against the Hand-E's grip force.

    PYTHONPATH=build/python python3 examples/python/grip_force_study.py [--trials N] [-o FIGURE.png]

A world with one heavy, slippery block is planned once per grip force; each plan then runs a
stress campaign whose block mass varies (log-normal) and whose start pose is perturbed. The
figure shows the success rate with its Wilson 95 % interval per force. Below the force the
block needs, the readiness check (grip) or the simulation (slip, drop) fails the plan.
"""

import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import dashbed  # noqa: E402

WORLD = """\
dashbed_world: 1
name: heavy_block_grip_{force}N
description: "One robot moves a heavy, slippery block into a bin at {force} N of grip force."
robots:
  - name: r0
    model: ur5e_hande
    base: {{xyz: [-0.45, 0, 0.75], yaw: 0}}
fixtures:
  - {{name: table, type: box, size: [1.6, 1.2, 0.75], pose: {{xyz: [0, 0, 0]}}, color: [0.6, 0.45, 0.3]}}
  - {{name: bin_red, type: bin, size: [0.3, 0.2, 0.1], pose: {{xyz: [0.1, -0.35, 0.75]}}, color: red, wall: 0.01}}
objects:
  - {{name: block, color: red, size: [0.04, 0.04, 0.04], mass: 1.2, friction: 0.4, pose: {{xyz: [0.1, 0.25, 0.77]}}}}
goals:
  - {{object: block, region: bin_red}}
controller:
  grip_force: {force}
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--forces", default="20,40,60,100,150", help="grip forces to try [N], comma-separated")
    parser.add_argument("--trials", type=int, default=20, help="trials per force")
    parser.add_argument("--sigma-mass", type=float, default=0.3, help="std dev of log(mass scale)")
    parser.add_argument("-o", "--output", default="grip_force.png")
    args = parser.parse_args()

    forces = [float(f) for f in args.forces.split(",")]
    rates = []
    for force in forces:
        world = dashbed.World.from_yaml(WORLD.format(force=force), f"grip_{force:g}N.yaml")
        result = dashbed.plan(world)
        if not result.solved:
            print(f"{force:g} N: {result.status}: {result.reason}", file=sys.stderr)
            return 4
        campaign = dashbed.stress(world, plan=result.plan, trials=args.trials, sigma_mass=args.sigma_mass, seed=1)
        point = campaign.summary["points"][0]
        rate, (lower, upper) = point["success_rate"], point["interval"]
        rates.append((rate, lower, upper))
        causes = {o.primary for o in campaign.outcomes if not o.passed}
        print(f"{force:5g} N: {rate:.2f} [{lower:.2f}, {upper:.2f}]"
              + (f"  failures: {', '.join(sorted(causes))}" if causes else ""))

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.errorbar(forces, [r for r, _, _ in rates], yerr=[[r - lo for r, lo, _ in rates], [up - r for r, _, up in rates]],
                marker="o", capsize=4)
    ax.set_xlabel("grip force [N]")
    ax.set_ylabel("success rate")
    ax.set_ylim(-0.05, 1.05)
    ax.set_title(f"1.2 kg block, friction 0.4, {args.trials} trials per force")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
