"""dashbed.kin: forward and inverse kinematics against the command line and each other."""

import json

import numpy as np
import pytest

import dashbed
from conftest import ONE_CUBE, cli

Q = [0.3, -1.2, 1.4, -1.8, -1.5, 0.4]


def test_fk_is_the_command_lines():
    pose = dashbed.kin.fk(Q)
    out = json.loads(cli("kin", "fk", *Q, "--json"))
    np.testing.assert_allclose(pose[:3, 3], out["pose"]["position"], atol=1e-12)
    np.testing.assert_allclose(pose[:3, :3], out["pose"]["rotation_rows"], atol=1e-12)


def test_ik_inverts_fk_in_a_world(one_cube_world):
    target = dashbed.kin.fk(Q, world=one_cube_world)
    solutions = dashbed.kin.ik(target, world=one_cube_world, seed=Q)
    assert solutions.ndim == 2 and solutions.shape[1] == 6 and 1 <= len(solutions) <= 8
    np.testing.assert_allclose(solutions[0], Q, atol=1e-9)  # nearest to the seed first
    for q in solutions:
        np.testing.assert_allclose(dashbed.kin.fk(q, world=one_cube_world), target, atol=1e-9)
    # base_link and world frames differ by the robot's base pose
    base = one_cube_world.robots[0].base_pose
    np.testing.assert_allclose(base @ dashbed.kin.fk(Q), target, atol=1e-12)


def test_out_of_reach_and_bad_input():
    far = np.eye(4)
    far[:3, 3] = [3.0, 0.0, 0.0]
    assert dashbed.kin.ik(far).shape == (0, 6)
    with pytest.raises(ValueError):
        dashbed.kin.ik(np.ones((4, 4)))
    with pytest.raises(ValueError):
        dashbed.kin.fk([0.0, 1.0])
    with pytest.raises(ValueError):
        dashbed.kin.fk(Q, frame="elbow_of_nowhere")
    with pytest.raises(ValueError):
        dashbed.kin.fk([float("nan")] * 6)
    with pytest.raises(ValueError):
        dashbed.kin.ik(dashbed.kin.fk(Q), seed=[float("inf")] * 6)
    # every joint, as simulate(samples=...) gives them: the fingers do not move the TCP
    np.testing.assert_array_equal(dashbed.kin.fk(Q + [0.01, 0.01]), dashbed.kin.fk(Q))
