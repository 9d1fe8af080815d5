"""god_finger.World: the same trajectory as the C++ world, and the calls a user makes."""
import math
import os
import time
import subprocess
import threading

import numpy as np
import pytest

import god_finger


def trace_script(world):
    """test/python/world_trace.cpp's script, through the Python API; its lines as numbers."""
    start0, velocity0 = [-0.06, 0.0, 0.05], [0.05, 0.0, 0.0]
    start1, velocity1 = [0.2, 0.2, 0.012], [0.0, 0.0, -0.008]
    world.add_finger(start0)
    world.add_finger(start1, orientation=[0.0, 0.0, 0.0, 1.0])
    lines = []
    for i in range(2000):
        t = (i + 1) * 0.001
        world.set_target(0, [s + v * t for s, v in zip(start0, velocity0)])
        half = 0.5 * (0.3 * t)
        world.set_target(1, [s + v * t for s, v in zip(start1, velocity1)],
                         orientation=[math.sin(half) * 1.0, math.sin(half) * 0.0, math.sin(half) * 0.0, math.cos(half)])
        world.step()
        if (i + 1) % 100:
            continue
        line = [float(i + 1)]
        for name in world.bodies:
            body = world.body(name)
            line += list(body.pose.reshape(-1)) + list(body.linear_velocity)
        for f in range(world.fingers):
            finger = world.finger(f)
            line += list(finger.position) + list(finger.force) + [float(len(finger.contacts))]
        lines.append(line)
    return lines


@pytest.mark.parametrize("model", ["god_object", "god_finger", "soft_finger"])
def test_two_seconds_equal_the_cpp_world(program, scene, model):
    out = subprocess.run([program("god_finger_world_trace"), scene("table_ball.urdf"), model], check=True,
                         capture_output=True, text=True)
    expected = [[float(x) for x in line.split()] for line in out.stdout.splitlines()]
    world = god_finger.World(scene("table_ball.urdf"), model)
    lines = trace_script(world)
    assert len(lines) == len(expected) == 20
    for got, want in zip(lines, expected):
        assert got == want, "step %d differs" % want[0]
    # The script did something: the ball was pushed along +x, the finger touched it.
    assert world.body("ball").position[0] > 0.02
    assert world.finger(1).oriented and world.finger(1).contact.body == "table"


def test_a_finger_touches_with_an_area(scene):
    world = god_finger.World(scene("table_ball.urdf"), r_max=0.01, n_sgo=8)
    finger = world.add_finger([0.0, 0.0, 0.09])
    world.set_target(finger, [0.0, 0.0, 0.075])  # 7 mm into the ball's top: about 2.8 N on 400 N/m
    world.step(300)
    state = world.finger(finger)
    contact = state.contact
    assert contact is not None and contact.body == "ball"
    assert contact.normal == pytest.approx([0, 0, 1], abs=0.05)
    assert 0.005 < contact.radius <= 0.01
    assert contact.sub_god_objects.shape == (8, 3)
    # Every sub-god-object lies on the ball's surface, at the area's radius from the point.
    centre = world.body("ball").center_of_mass
    np.testing.assert_allclose(np.linalg.norm(contact.sub_god_objects - centre, axis=1), 0.04, atol=2e-4)
    assert state.force[2] == pytest.approx(-world.params["coupling_stiffness"] * 0.0 - 400 * (0.075 - state.position[2]),
                                           rel=0.05)
    assert state.force[2] > 2.0


def test_the_step_profile_and_counters(scene):
    # Every step timed (profile_every=1): the stages sum to the step, the touching finger's contact
    # area takes time; the counters say what the solver did.
    world = god_finger.World(scene("table_ball.urdf"), profile_every=1)
    assert world.step_profile["step"] == -1  # nothing timed yet
    finger = world.add_finger([0.0, 0.0, 0.09])
    world.set_target(finger, [0.0, 0.0, 0.075])
    world.step(300)
    profile = world.step_profile
    stages = ["coupling", "wake", "collide", "contact_areas", "solve", "record", "soft_bodies", "sleep", "escapees",
              "overlap"]
    assert profile["step"] == 300
    assert sum(profile[stage + "_ns"] for stage in stages) == profile["total_ns"]
    assert profile["contact_areas_ns"] > 0 and profile["solve_ns"] > 0
    counters = world.counters
    assert counters["solver_contact_rows"] > 0 and counters["solver_iterations"] > 0
    assert counters["solver_proxy_points"] >= 1
    assert 0.0 <= counters["deepest_penetration"] < 0.005
    assert counters["dropped_contacts_total"] == 0 and counters["rejected_targets"] == 0
    # One step in 16 by default.
    world = god_finger.World(scene("table_ball.urdf"))
    assert world.params["profile_every"] == 16
    world.step(20)
    assert world.step_profile["step"] == 17


def test_model_changes_the_run(scene):
    def push(model_at_start, model_later):
        world = god_finger.World(scene("table_ball.urdf"), model=model_at_start)
        finger = world.add_finger([-0.06, 0.0, 0.05])
        for i in range(1500):
            if i == 200:
                world.contact_model = model_later
            world.set_target(finger, [-0.06 + 0.05 * (i + 1) * 0.001, 0.0, 0.05])
            world.step()
        return world

    world = push("god_object", "god_finger")
    assert world.contact_model == "god_finger" == world.params["model"]
    same = push("god_finger", "god_finger")
    other = push("god_object", "god_object")
    np.testing.assert_array_equal(world.body("ball").pose, same.body("ball").pose)  # changed before the touch
    assert not np.array_equal(other.body("ball").pose, same.body("ball").pose)
    with pytest.raises(god_finger.Error, match="contact model 'cone' is not one of"):
        world.contact_model = "cone"
    assert world.contact_model == "god_finger"


def test_reset_repeats_the_run_bit_for_bit(scene):
    world = god_finger.World(scene("table_ball.urdf"))
    finger = world.add_finger([-0.06, 0.0, 0.05])

    def run():
        for i in range(800):
            world.set_target(finger, [-0.06 + 0.05 * (i + 1) * 0.001, 0.0, 0.05])
            world.step()
        return world.body("ball").pose.copy(), world.time, world.steps

    first = run()
    world.reset()
    assert world.time == 0.0 and world.steps == 0
    second = run()
    np.testing.assert_array_equal(first[0], second[0])
    assert first[1:] == second[1:] == (pytest.approx(0.8), 800)


def test_bodies_joints_and_wrenches(scene):
    door = god_finger.World(scene("door.urdf"))
    assert door.joints, "the door has a hinge"
    hinge = door.joints[0]
    assert door.joint(hinge).kind == "revolute"
    panel = [name for name in door.bodies if not door.body(name).static][0]
    door.apply_wrench(panel, [0.0, 0.0, 0.0], [0.0, 0.0, 2.0])
    door.step(50)
    assert door.joint(hinge).position != 0.0
    assert door.joint(hinge).velocity != 0.0

    world = god_finger.World(scene("table_ball.urdf"))
    ball = world.body("ball")
    assert not ball.static and ball.mass == pytest.approx(0.1)
    world.apply_wrench("ball", [0.5, 0.0, 0.0])
    world.step()
    assert world.body("ball").linear_velocity[0] > 0.0
    assert world.body("table").static


def test_spawn_and_remove(root, scene):
    world = god_finger.World(scene("table_ball.urdf"))
    before = list(world.bodies)
    warnings = world.spawn(scene("table_box.urdf"), name="boxes", xyz=[0.3, 0.0, 0.0])
    assert isinstance(warnings, list)
    assert len(world.bodies) > len(before)
    added = [name for name in world.bodies if name not in before]
    assert all(name.startswith("boxes") for name in added)
    world.step(10)
    assert world.remove("boxes") == len(added)
    assert world.bodies == before
    with pytest.raises(god_finger.Error, match="no body 'boxes"):
        world.body(added[0])


def test_snapshot_holds_everything(scene):
    world = god_finger.World(scene("table_ball.urdf"))
    world.add_finger([0.0, 0.0, 0.09])
    world.step(5)
    snap = world.snapshot()
    assert snap["steps"] == 5 and snap["time"] == pytest.approx(0.005)
    assert set(snap["bodies"]) == set(world.bodies)
    assert len(snap["fingers"]) == 1 and snap["model"] == "god_finger"


def test_params_by_table_names(scene):
    world = god_finger.World(scene("table_ball.urdf"), r_max=0.008, n_sgo=12, walk="project", pad_solver="points",
                             coupling_stiffness=300.0, time_step=0.0005)
    params = world.params
    assert params["r_max"] == 0.008 and params["n_sgo"] == 12 and params["walk"] == "project"
    assert params["pad_solver"] == "points" and params["coupling_stiffness"] == 300.0
    assert params["time_step"] == 0.0005
    world.add_finger([0.0, 0.0, 0.2])
    world.step(4)
    assert world.time == pytest.approx(0.002)


def test_oriented_finger_reports_orientation(scene):
    world = god_finger.World(scene("table_box.urdf"))
    top = max(world.body(name).position[2] for name in world.bodies) + 0.1
    finger = world.add_finger([0.0, 0.0, top], orientation=[0, 0, 0, 1])
    assert world.finger(finger).oriented
    q = [math.sin(0.1), 0.0, 0.0, math.cos(0.1)]
    world.set_target(finger, [0.0, 0.0, top], orientation=q)
    world.step(400)
    state = world.finger(finger)
    np.testing.assert_allclose(state.target_orientation, q, atol=1e-12)
    assert abs(state.orientation[0]) > 0.05  # the proxy turned towards it


def test_step_releases_the_gil(scene):
    world = god_finger.World(scene("table_clutter.urdf"))
    started, times = threading.Event(), {}

    def run():
        started.set()
        world.step(3000)
        times["returned"] = time.monotonic()

    thread = threading.Thread(target=run)
    thread.start()
    assert started.wait(timeout=60)
    # This Python line needs the GIL: without the release it would run only once step returned.
    times["main_ran"] = time.monotonic()
    thread.join()
    assert times["main_ran"] < times["returned"] - 0.05


@pytest.mark.parametrize("file, body", [("urdf/lists/table_objects.yaml", "ball"),
                                        ("urdf/objects/stool.urdf.xacro", None),
                                        ("urdf/scenes/soft_block.urdf", None)])
def test_any_scene_the_loader_takes(root, file, body):
    """A scene list, a xacro object file and a scene with a soft body load and step as URDFs do."""
    world = god_finger.World(os.path.join(root, file))
    assert world.bodies
    name = body or world.bodies[-1]
    top = max(world.body(n).position[2] for n in world.bodies) + 0.3
    finger = world.add_finger([world.body(name).center_of_mass[0], world.body(name).center_of_mass[1], top])
    world.step(100)
    assert world.steps == 100 and np.all(np.isfinite(world.finger(finger).position))
    assert all(np.all(np.isfinite(world.body(n).pose)) for n in world.bodies)
