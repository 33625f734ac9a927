"""dashbed.stress: the command line's campaign, the same outcomes."""

import json

import pytest

import dashbed
from conftest import ONE_CUBE, cli


def test_a_campaign_is_the_command_lines(tmp_path, one_cube_world, one_cube_plan):
    plan_file = tmp_path / "plan.json"
    result = dashbed.stress(one_cube_world, plan=one_cube_plan.save(plan_file), trials=3, seed=4, sigma_xy=0.004, threads=2,
                            out=str(tmp_path / "py"))
    cli("stress", ONE_CUBE, "--plan", plan_file, "-n", 3, "--seed", 4, "--sigma-xy", 0.004, "-j", 2,
        "--out", tmp_path / "cli")
    assert (tmp_path / "py/summary.json").read_text() == (tmp_path / "cli/summary.json").read_text()
    assert (tmp_path / "py/trials.csv").read_text() == (tmp_path / "cli/trials.csv").read_text()
    summary = json.loads((tmp_path / "cli/summary.json").read_text())
    assert result.summary == summary
    assert [o.index for o in result.outcomes] == [0, 1, 2]
    passed = sum(o.passed for o in result.outcomes)
    assert result.success_rate == [pytest.approx(passed / 3)]
    assert result.passed
    assert result.text().startswith("stress: one_cube, replay: ../plan.json")


def test_min_success_and_bad_settings(one_cube_world, one_cube_plan):
    # a huge offset moves cubes where the plan's grasp misses them
    result = dashbed.stress(one_cube_world, plan=one_cube_plan, trials=2, sigma_xy=0.03, min_success=1.0, threads=1)
    assert result.success_rate[0] < 1.0 and not result.passed
    failed = [o for o in result.outcomes if not o.passed]
    assert failed[0].primary is not None and failed[0].primary in failed[0].classes and failed[0].failure
    with pytest.raises(ValueError):
        dashbed.stress(one_cube_world, plan=one_cube_plan, trials=0)
    with pytest.raises(ValueError):
        dashbed.stress(one_cube_world, plan=one_cube_plan, mode="replan")
    with pytest.raises(ValueError):
        dashbed.stress(one_cube_world, plan=one_cube_plan, min_success=float("nan"))
