"""Whatever a script passes, the module raises TypeError or ValueError and never takes the
interpreter down: every call with every kind of wrong argument, in a process of its own (a crash
would be its exit status), then Ctrl-C stops a long step()."""
import os
import signal
import subprocess
import sys
import textwrap
import threading

import god_finger

BAD = ["None", "'x'", "float('nan')", "float('inf')", "-1", "10**30", "[]", "[1, 2]", "[[1, 2, 3]]",
       "np.zeros((3, 3))", "np.array(['a', 'b', 'c'])", "object()", "{}", "b'abc'"]

CALLS = [
    "world.add_finger({0})", "world.add_finger([0, 0, 0.3], orientation={0})",
    "world.add_finger([0, 0, 0.3], coupling={0})", "world.set_target({0}, [0, 0, 0.3])",
    "world.set_target(0, {0})", "world.set_target(0, [0, 0, 0.3], orientation={0})",
    "world.set_target(0, [0, 0, 0.3], velocity={0})", "world.finger({0})", "world.step({0})",
    "world.body({0})", "world.joint({0})", "world.apply_wrench('ball', {0})",
    "world.apply_wrench('ball', [0, 0, 0], {0})", "world.spawn({0})", "world.spawn(scene, xyz={0})",
    "world.remove({0})", "setattr(world, 'contact_model', {0})", "god_finger.World({0})",
    "god_finger.World(scene, r_max={0})", "god_finger.World(scene, model={0})", "god_finger.load_mesh({0})",
    "god_finger.Mesh({0}, [[0, 1, 2]])", "god_finger.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], {0})",
    "god_finger.contact_area(mesh, {0}, [0, 0, 1], [0, 0, -0.01])",
    "god_finger.contact_area(mesh, [0.1, 0.1, 0], {0}, [0, 0, -0.01])",
    "god_finger.contact_area(mesh, [0.1, 0.1, 0], [0, 0, 1], {0})",
    "god_finger.contact_area(mesh, [0.1, 0.1, 0], [0, 0, 1], force={0})",
    "god_finger.contact_area(mesh, [0.1, 0.1, 0], [0, 0, 1], [0, 0, -0.01], depth={0})",
    "god_finger.run_experiment({0})", "god_finger.run_experiment('slide', duration={0})",
]


def test_bad_arguments_raise_and_never_crash(scene):
    script = textwrap.dedent("""
        import numpy as np
        import god_finger
        scene = {scene!r}
        world = god_finger.World(scene)
        world.add_finger([0.0, 0.0, 0.3])
        mesh = god_finger.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        raised = 0
        for call in {calls!r}:
            for bad in {bad!r}:
                try:
                    eval(call.format(bad))
                except (TypeError, ValueError):
                    raised += 1
        world.step(10)
        assert world.steps == 10
        print("raised", raised)
    """).format(scene=scene("table_ball.urdf"), calls=CALLS, bad=BAD)
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-2000:]
    raised = int(result.stdout.split()[-1])
    # Most combinations are wrong; a few are right by accident (step(-1) is not, step(10**30) is
    # too large for a long: both raise; world.finger(-1) raises; a float for `depth` is fine).
    assert raised > 0.8 * len(CALLS) * len(BAD)


def test_ctrl_c_stops_a_long_step(scene):
    world = god_finger.World(scene("table_clutter.urdf"))
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        world.step(10_000_000)  # hours: only the interrupt ends it
        raise AssertionError("step ran to its end")
    except KeyboardInterrupt:
        pass
    finally:
        timer.cancel()
    steps = world.steps
    assert 0 < steps < 10_000_000 and steps % 1000 == 0
    world.step(5)
    assert world.steps == steps + 5
