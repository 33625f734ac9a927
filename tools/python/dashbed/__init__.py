"""dashbed: DaSH multi-robot task and motion planning for UR5e arms with Robotiq Hand-E
grippers, checked in a Bullet simulation.

    import dashbed
    world = dashbed.World.load("worlds/default.yaml")
    result = dashbed.plan(world, method="greedy", seed=1)
    report = dashbed.simulate(world, result.plan, samples=30.0)
    print(report.passed, [a.id for a in report.failed_actions])

The same world, method and seed give the same plan bytes as `dashbed plan`; the same plan
gives the same report as `dashbed sim`. docs/python.md is the manual.
"""

from dashbed._dashbed import (  # noqa: F401  (the package's interface)
    Action,
    ActionReport,
    Event,
    Fixture,
    Goal,
    GripperCommand,
    InputError,
    Measurement,
    Object,
    Plan,
    PlanError,
    PlanningResult,
    ReadinessCheck,
    Region,
    Report,
    ReportError,
    Robot,
    RobotExecution,
    StressResult,
    TrialOutcome,
    World,
    WorldError,
    gen_shelf,
    gen_sort,
    kin,
    plan,
    render,
    simulate,
    stress,
)

__all__ = [name for name in dir() if not name.startswith("_")]
