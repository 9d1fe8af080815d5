"""Every bad input raises god_finger.Error (a ValueError) with the C++ message, and loses nothing."""
import math

import numpy as np
import pytest

import god_finger


def test_missing_scene_file(tmp_path):
    with pytest.raises(ValueError, match="nowhere.urdf"):
        god_finger.World(str(tmp_path / "nowhere.urdf"))


def test_malformed_urdf(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r"><link name="a"><inertial><mass value="x"/></inertial></link>')
    with pytest.raises(god_finger.Error, match="bad.urdf"):
        god_finger.World(str(bad))


def test_unknown_and_out_of_range_parameters(scene):
    with pytest.raises(god_finger.Error, match=r"unknown parameter 'rmax' \(the world's parameters: .*r_max"):
        god_finger.World(scene("table_ball.urdf"), rmax=0.01)
    with pytest.raises(god_finger.Error, match=r"^parameter 'r_max' = -0.01 is out of range \(0, 1000\] \(m\)$"):
        god_finger.World(scene("table_ball.urdf"), r_max=-0.01)
    with pytest.raises(god_finger.Error, match="parameter 'walk' = 'zigzag' is not one of project, unfold"):
        god_finger.World(scene("table_ball.urdf"), walk="zigzag")
    with pytest.raises(god_finger.Error, match="parameter 'time_step'"):
        god_finger.World(scene("table_ball.urdf"), time_step=1.0)
    with pytest.raises(god_finger.Error, match="model"):
        god_finger.World(scene("table_ball.urdf"), model="cone")
    with pytest.raises(god_finger.Error, match="n_sgo"):
        god_finger.contact_area(god_finger.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), [0.1, 0.1, 0],
                                [0, 0, 1], [0, 0, -0.01], n_sgo=1000)


def test_nan_targets_and_wrong_shapes(scene):
    world = god_finger.World(scene("table_ball.urdf"))
    finger = world.add_finger([0.0, 0.0, 0.2])
    with pytest.raises(god_finger.Error, match="position must be finite"):
        world.set_target(finger, [math.nan, 0.0, 0.2])
    with pytest.raises(god_finger.Error, match=r"position must be 3 numbers, shape \(3,\), not shape \(2,\)"):
        world.set_target(finger, [0.0, 0.2])
    with pytest.raises(god_finger.Error, match=r"not shape \(2, 3\)"):
        world.set_target(finger, np.zeros((2, 3)))
    with pytest.raises(god_finger.Error, match="position must be 3 numbers, not str"):
        world.set_target(finger, "up")
    with pytest.raises(god_finger.Error, match="unit quaternion"):
        world.set_target(finger, [0, 0, 0.2], orientation=[0, 0, 0, 0.1])
    with pytest.raises(god_finger.Error, match="no finger 3"):
        world.finger(3)
    with pytest.raises(god_finger.Error, match="not both"):
        world.set_target(finger, [0, 0, 0.2], orientation=[0, 0, 0, 1], velocity=[0, 0, 0])
    with pytest.raises(god_finger.Error, match="n must be >= 0"):
        world.step(-1)
    with pytest.raises(god_finger.Error, match=r"Mesh: vertices must be an array of shape \(n, 3\)"):
        god_finger.Mesh(np.zeros((4, 2)), [[0, 1, 2]])
    with pytest.raises(god_finger.Error, match="names vertex 7"):
        god_finger.Mesh(np.zeros((3, 3)), [[0, 1, 7]])
    # Nothing was lost: the world steps on from where it was.
    world.step(10)
    assert world.steps == 10 and world.rejected_targets == 0


def test_a_finger_inside_a_body(scene):
    world = god_finger.World(scene("table_ball.urdf"))
    with pytest.raises(god_finger.ProxyInsideBodyError, match="ball"):
        world.add_finger([0.0, 0.0, 0.04])
    assert world.fingers == 0
    assert world.add_finger([0.0, 0.0, 0.04], allow_inside=True) == 0


def test_removed_and_unknown_names(scene, tmp_path):
    world = god_finger.World(scene("table_ball.urdf"))
    assert world.remove("ball") == 1
    with pytest.raises(god_finger.Error, match=r"no body 'ball' in the scene \(its bodies: table\)"):
        world.body("ball")
    with pytest.raises(god_finger.Error, match="no body 'ball'"):
        world.apply_wrench("ball", [1, 0, 0])
    with pytest.raises(god_finger.Error, match="ball"):
        world.remove("ball")
    with pytest.raises(god_finger.Error, match="no joint 'hinge'"):
        world.joint("hinge")
    # A failed spawn leaves the world as it was.
    missing = str(tmp_path / "missing.urdf")
    with pytest.raises(god_finger.Error, match="missing.urdf"):
        world.spawn(missing, name="x")
    assert world.bodies == ["table"]
    world.step(5)
    assert world.steps == 5


def test_missing_and_broken_meshes(tmp_path):
    with pytest.raises(god_finger.Error, match="nothing.stl"):
        god_finger.load_mesh(str(tmp_path / "nothing.stl"))
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(god_finger.Error, match="broken.off"):
        god_finger.load_mesh(str(broken))
