"""dashbed.simulate: the command line's reports byte for byte, verdicts, samples, threads."""

import json
import threading

import numpy as np
import pytest

import dashbed
from conftest import ONE_CUBE, cli, run_cli


def test_reports_are_the_command_lines_bytes(tmp_path, one_cube_world, one_cube_plan):
    plan_file = tmp_path / "plan.json"
    plan = one_cube_plan.save(plan_file)
    for side in ("py", "cli"):
        (tmp_path / side).mkdir()
    report = dashbed.simulate(one_cube_world, plan, report=str(tmp_path / "py/report.json"),
                              junit=str(tmp_path / "py/junit.xml"))
    cli("sim", plan_file, "--world", ONE_CUBE, "--report", tmp_path / "cli/report.json",
        "--junit", tmp_path / "cli/junit.xml")
    for name in ("report.json", "junit.xml", "report.stills/final.png"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert report.to_json() == (tmp_path / "py/report.json").read_text()
    assert dashbed.Report.load(str(tmp_path / "cli/report.json")).to_json() == report.to_json()


def test_verdicts_and_measurements(one_cube_world, one_cube_plan):
    report = dashbed.simulate(one_cube_world, one_cube_plan)
    assert report.passed and report.ready and report.execution_passed
    assert [a.type for a in report.actions] == ["pick", "place"]
    assert report.failed_actions == []
    pick = report.actions[0]
    assert pick.passed and pick.verdict == "passed" and pick.failure == ""
    slip = next(m for m in pick.measurements if m.name == "slip")
    assert slip.unit == "m" and slip.comparison == "<=" and slip.passed
    assert 0 <= slip.value <= slip.threshold
    assert pick.observed_start is not None and pick.planned_start <= pick.observed_start
    assert report.summary == {"actions": 2, "passed": 2, "failed": 0, "execution": "passed", "execution_failure": "",
                              "readiness": "passed", "verdict": "passed"}
    assert report.robots[0].robot == "r0" and report.robots[0].max_effort_ratio <= 1.0
    assert {c.name for c in report.readiness} >= {"joint speed", "joint effort", "payload"}
    assert report.text(quiet=True).startswith("PASSED: 2 of 2 actions passed")
    assert report.samples is None


def test_a_failing_plan_fails_with_its_check(tmp_path, one_cube_world, one_cube_plan):
    # the gripper never closes: the pick must fail, naming the missing contact
    data = json.loads(one_cube_plan.to_json())
    data["gripper"] = [c for c in data["gripper"] if c["command"] != "close"]
    plan = dashbed.Plan.from_json(json.dumps(data))
    report = dashbed.simulate(one_cube_world, plan)
    assert not report.passed
    failed = report.failed_actions
    assert failed and failed[0].type == "pick" and failed[0].verdict == "failed"
    assert "does not close r0's gripper" in failed[0].failure
    place = failed[1]
    assert place.type == "place" and any(not m.passed for m in place.measurements)
    assert report.summary["verdict"] == "failed"


def test_samples_follow_the_simulation(one_cube_world, one_cube_plan):
    report = dashbed.simulate(one_cube_world, one_cube_plan, samples=20.0)
    s = report.samples
    n = len(s["times"])
    assert s["rate"] == 20.0 and s["robots"] == ["r0"] and s["objects"] == ["cube_0"]
    assert n == pytest.approx(one_cube_plan.duration * 20.0, abs=30)  # the plan, then the settling tail
    np.testing.assert_allclose(np.diff(s["times"]), 0.05, atol=one_cube_world.time_step + 1e-9)
    assert s["joint_positions"].shape == (n, 1, len(s["joints"]))
    assert s["link_poses"].shape == (n, 1, len(s["links"]), 7)
    assert s["object_poses"].shape == (n, 1, 7)
    # quaternions are unit length
    np.testing.assert_allclose(np.linalg.norm(s["object_poses"][:, 0, 3:], axis=1), 1.0, atol=1e-9)
    # the cube starts where the world puts it and ends in the bin
    np.testing.assert_allclose(s["object_poses"][0, 0, :2], one_cube_world.objects[0].position[:2], atol=2e-3)
    bin_region = next(r for r in one_cube_world.regions if r.name == "bin_red")
    end = s["object_poses"][-1, 0, :3]
    assert np.all(np.abs(end[:2] - bin_region.pose[:2, 3]) <= bin_region.size[:2] / 2)
    # the TCP link's sampled pose agrees with forward kinematics of the sampled joints
    tcp = s["links"].index("tcp")
    k = n // 2
    fk = dashbed.kin.fk(s["joint_positions"][k, 0, :6], world=one_cube_world)
    np.testing.assert_allclose(s["link_poses"][k, 0, tcp, :3], fk[:3, 3], atol=1e-9)
    # the signals agree with the report's extremes and the world's grip force
    assert s["tracking_error"].shape == (n, 1) and s["effort_ratio"].shape == (n, 1)
    assert np.max(s["tracking_error"]) <= report.robots[0].max_tracking_error + 1e-12
    assert 0 < np.max(s["effort_ratio"]) <= report.robots[0].max_effort_ratio + 1e-12
    pick = report.actions[0]
    held = (s["times"] > pick.observed_end) & (s["times"] < report.actions[1].planned_start)
    assert held.any() and np.all(s["grip_force"][held, 0] > 0.5 * one_cube_world.grip_force)
    assert np.all(s["grip_force"][s["times"] < pick.planned_start, 0] == 0)
    with pytest.raises(ValueError):
        dashbed.simulate(one_cube_world, one_cube_plan, samples=0.0)


def test_parallel_simulations_give_the_serial_reports(one_cube_world, one_cube_plan):
    serial = dashbed.simulate(one_cube_world, one_cube_plan).to_json()
    results = [None] * 3
    threads = [threading.Thread(target=lambda i=i: results.__setitem__(
        i, dashbed.simulate(one_cube_world, one_cube_plan).to_json())) for i in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [serial] * 3


def test_a_plan_for_another_world_is_refused(one_cube_plan):
    other = dashbed.gen_sort(robots=2, cubes=2)
    with pytest.raises(dashbed.PlanError) as caught:
        dashbed.simulate(other, one_cube_plan)
    assert caught.value.field is not None


def test_render_writes_frames(tmp_path, one_cube_world, one_cube_plan):
    report = dashbed.render(one_cube_world, one_cube_plan, out=str(tmp_path / "frames"), fps=2, start=1, until=3,
                            width=160, height=120)
    assert report.frames_written == 5
    assert sorted(p.name for p in (tmp_path / "frames").iterdir())[0].endswith(".png")
    with pytest.raises(ValueError):
        dashbed.render(one_cube_world, one_cube_plan)
    with pytest.raises(ValueError):  # more frames than simulation steps
        dashbed.render(one_cube_world, one_cube_plan, out=str(tmp_path / "many"), fps=1e9)


def test_html_replay(tmp_path, one_cube_world, one_cube_plan):
    report = dashbed.simulate(one_cube_world, one_cube_plan, html=str(tmp_path / "run.html"))
    page = (tmp_path / "run.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and "dashbed replay: one_cube PASSED" in page
    assert report.passed
