"""dashbed.plan and dashbed.Plan: the command line's plans byte for byte, numpy arrays, errors."""

import json

import numpy as np
import pytest

import dashbed
from conftest import ONE_CUBE, ROOT, cli


@pytest.mark.parametrize("method", ["greedy", "optimal"])
def test_plans_are_the_command_lines_bytes(tmp_path, method):
    world = dashbed.World.load(str(ROOT / "worlds/default.yaml"))
    result = dashbed.plan(world, method=method, seed=3)
    assert result.status == "solved" and result.solved and result.reason == ""
    out = tmp_path / "plan.json"
    cli("plan", ROOT / "worlds/default.yaml", "--method", method, "--seed", 3, "-o", out)
    assert result.plan.to_json() == out.read_text()
    stats = result.statistics
    assert stats["method"] == method and stats["status"] == "solved"
    assert stats["makespan"] == pytest.approx(result.plan.duration, abs=1e-9)


def test_trajectories_as_arrays(one_cube_world, one_cube_plan):
    p = one_cube_plan
    assert p.robots == ["r0"] and p.world == "one_cube" and p.seed == 1
    t = p.trajectory("r0")
    n = len(t["times"])
    assert n > 2
    assert t["positions"].shape == (n, 6) and t["velocities"].shape == (n, 6)
    assert t["joint_names"][0] == "shoulder_pan_joint"
    assert np.all(np.diff(t["times"]) > 0)
    # the file's numbers, in radians: the same as in the JSON
    points = json.loads(p.to_json())["robots"][0]["points"]
    np.testing.assert_array_equal(t["positions"][3], points[3]["q"])
    np.testing.assert_array_equal(t["times"], [point["t"] for point in points])
    np.testing.assert_allclose(t["positions"][0], one_cube_world.robots[0].home, atol=1e-12)
    with pytest.raises(KeyError):
        p.trajectory("r9")
    kinds = [a.type for a in p.actions]
    assert kinds == ["pick", "place"]
    place = p.actions[1]
    assert place.object == "cube_0" and place.region == "bin_red" and place.start >= p.actions[0].end
    assert [c.action for c in p.gripper][:2] == ["open", "close"]
    assert p.duration >= place.end


def test_save_and_load_round_trip(tmp_path, one_cube_plan):
    file = tmp_path / "p.json"
    saved = one_cube_plan.save(file)
    assert saved.file == str(file) and one_cube_plan.file == ""
    again = dashbed.Plan.load(file)
    assert again.file == str(file)
    assert again.to_json() == saved.to_json() == one_cube_plan.to_json() == file.read_text()
    assert dashbed.Plan.from_json(file.read_text()).to_json() == file.read_text()


def test_bad_plans_raise_plan_errors_with_their_pointer(tmp_path, one_cube_plan):
    data = json.loads(one_cube_plan.to_json())
    data["robots"][0]["points"][2]["t"] = -1.0
    with pytest.raises(dashbed.PlanError) as caught:
        dashbed.Plan.from_json(json.dumps(data), "edited.json")
    assert caught.value.file == "edited.json"
    assert caught.value.field == "/robots/0/points/2/t"
    assert caught.value.line is None
    with pytest.raises(dashbed.PlanError):
        dashbed.Plan.load(str(tmp_path / "none.json"))


def test_infeasible_and_bad_choices():
    # the cube stands against the bin's wall where no grasp is free of it
    world = dashbed.World.load(str(ROOT / "worlds/handwritten/u07_tricky_cubes.yaml"))
    result = dashbed.plan(world)
    assert result.status == "infeasible" and result.plan is None and not result.solved
    assert "no collision-free grasp of cube_0" in result.reason
    with pytest.raises(ValueError):
        dashbed.plan(world, method="fastest")
    with pytest.raises(ValueError):
        dashbed.plan(world, time_budget=-1.0)
    with pytest.raises(ValueError):
        dashbed.plan(world, time_budget=float("inf"))


def test_same_seed_same_plan(one_cube_world):
    first = dashbed.plan(one_cube_world, seed=5).plan.to_json()
    assert dashbed.plan(one_cube_world, seed=5).plan.to_json() == first
