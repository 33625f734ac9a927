"""dashbed.World: loading, read-only access, errors as exceptions with their parts."""

import numpy as np
import pytest

import dashbed
from conftest import ONE_CUBE, ROOT, cli, run_cli


def test_load_gives_the_file_contents(one_cube_world):
    w = one_cube_world
    assert w.name == "one_cube"
    assert w.file == str(ONE_CUBE)
    assert [r.name for r in w.robots] == ["r0"]
    np.testing.assert_allclose(w.robots[0].base_pose[:3, 3], [-0.45, 0.0, 0.75])
    cube = w.objects[0]
    assert cube.name == "cube_0" and cube.object_class == "red"
    np.testing.assert_allclose(cube.position, [0.1, 0.25, 0.77])
    pose = cube.pose
    assert pose.shape == (4, 4)
    np.testing.assert_allclose(pose[:3, :3], [[np.cos(0.2), -np.sin(0.2), 0], [np.sin(0.2), np.cos(0.2), 0], [0, 0, 1]],
                               atol=1e-12)
    np.testing.assert_allclose(cube.size, [0.04, 0.04, 0.04])
    assert cube.mass > 0
    assert w.goal_region("cube_0") == "bin_red"
    assert "bin_red" in [r.name for r in w.regions]
    assert {f.type for f in w.fixtures} == {"box", "bin"}
    with pytest.raises(KeyError):
        w.goal_region("no_such_cube")


def test_world_file_errors_carry_file_line_and_field(tmp_path):
    text = ONE_CUBE.read_text().replace("xyz: [0.1, 0.25, 0.77]", "xyz: [0.1, 0.25]")
    bad = tmp_path / "bad.yaml"
    bad.write_text(text)
    with pytest.raises(dashbed.WorldError) as caught:
        dashbed.World.load(str(bad))
    e = caught.value
    assert e.file == str(bad)
    assert e.line == next(i for i, line in enumerate(text.splitlines(), 1) if "[0.1, 0.25]" in line)
    assert e.field == "objects[0].pose.xyz"
    assert "3" in e.problem
    assert str(e).startswith(f"{bad}:{e.line}:{e.column}: objects[0].pose.xyz: ")
    # the same message as the command line's
    assert str(e) in run_cli("plan", bad, expect=3).stderr


def test_errors_are_value_errors_and_name_what_is_missing(tmp_path):
    with pytest.raises(dashbed.WorldError) as caught:
        dashbed.World.load(str(tmp_path / "missing.yaml"))
    assert caught.value.file == str(tmp_path / "missing.yaml")
    assert caught.value.line is None and caught.value.field is None
    assert "no such file" in caught.value.problem
    assert isinstance(caught.value, dashbed.InputError) and isinstance(caught.value, ValueError)
    with pytest.raises(dashbed.WorldError) as caught:
        dashbed.World.from_yaml("dashbed_world: 1\nname: [\n", "typed.yaml")
    assert caught.value.file == "typed.yaml" and caught.value.line is not None


def test_reach_is_checked_on_load():
    text = ONE_CUBE.read_text().replace("xyz: [0.1, 0.25, 0.77]", "xyz: [0.75, 0.55, 0.77]")
    with pytest.raises(dashbed.WorldError) as caught:
        dashbed.World.from_yaml(text, "far.yaml")
    assert caught.value.field == "objects[0].pose"
    assert "out of every robot's reach" in caught.value.problem


def test_generators_match_the_command_line():
    world = dashbed.gen_sort(robots=4, cubes=8, start="random", seed=3)
    assert world.to_yaml() == cli("gen", "sort", "--robots", 4, "--cubes", 8, "--start", "random", "--seed", 3)
    assert len(world.robots) == 4 and len(world.objects) == 8
    shelf = dashbed.gen_shelf(objects=6, seed=2)
    assert shelf.to_yaml() == cli("gen", "shelf", "--objects", 6, "--seed", 2)
    with pytest.raises(ValueError):
        dashbed.gen_sort(cubes=0)
    # a world read back from its own text is the same world
    again = dashbed.World.from_yaml(world.to_yaml())
    assert again.to_yaml() == world.to_yaml()


def test_default_world_is_the_one_in_worlds():
    assert dashbed.World.default().to_yaml() == dashbed.World.load(str(ROOT / "worlds/default.yaml")).to_yaml()
