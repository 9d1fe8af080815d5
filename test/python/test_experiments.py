"""run_experiment gives god_finger_experiment's numbers: every scenario, every model."""
import json
import subprocess

import numpy as np
import pytest

import god_finger


def tool_json(program, *arguments):
    out = subprocess.run([program("god_finger_experiment"), *arguments], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def as_json(value):
    """A measured number as the tool writes it: 9 significant digits, None when not finite."""
    if not np.isfinite(value):
        return None
    return float("%.9g" % value)


def test_lists_are_the_tools(program):
    out = subprocess.run([program("god_finger_experiment"), "--list-scenarios"], check=True, capture_output=True,
                         text=True)
    assert god_finger.scenarios() == out.stdout.split()
    out = subprocess.run([program("god_finger_experiment"), "--list-models"], check=True, capture_output=True,
                         text=True)
    assert god_finger.models() == out.stdout.split()
    assert len(god_finger.scenarios()) == 14


@pytest.mark.parametrize("model", ["god_object", "god_finger", "soft_finger"])
@pytest.mark.parametrize("scenario", god_finger.scenarios())
def test_metrics_equal_the_tools(program, scenario, model):
    expected = tool_json(program, "--scenario", scenario, "--model", model)
    result = god_finger.run_experiment(scenario, model)
    assert result["scenario"] == scenario and result["model"] == model
    assert result["steps"] == expected["steps"]
    assert result["nan"] == expected["nan"]
    assert as_json(result["max_penetration_m"]) == expected["max_penetration_m"]
    assert as_json(result["duration_s"]) == expected["duration_s"]
    assert sorted(result["metrics"]) == sorted(expected["metrics"])
    for name, value in result["metrics"].items():
        assert as_json(value) == expected["metrics"][name], name
    # The series: one row per step, the object's time stamps the steps'.
    series = result["series"]
    assert len(series["t"]) == result["steps"] - result["nan"]
    assert series["t"][-1] == pytest.approx(result["duration_s"], rel=1e-9)


def test_series_equal_the_tools_csv(program, tmp_path):
    csv = tmp_path / "slide.csv"
    tool_json(program, "--scenario", "slide", "--model", "god_finger", "--csv", str(csv))
    table = np.genfromtxt(csv, delimiter=",", names=True)
    series = god_finger.run_experiment("slide", "god_finger")["series"]
    assert list(series) == list(table.dtype.names)
    for name in table.dtype.names:
        np.testing.assert_array_equal(series[name], table[name], err_msg=name)


def test_options_reach_the_run(program):
    expected = tool_json(program, "--scenario", "slide", "--model", "god_object", "--duration", "0.5",
                         "--push-height", "0.02", "--seed", "3")
    result = god_finger.run_experiment("slide", "god_object", duration=0.5, push_height=0.02, seed=3)
    assert result["steps"] == 500 == expected["steps"]
    for name, value in result["metrics"].items():
        assert as_json(value) == expected["metrics"][name], name


def test_fake_hand_equals_the_tools(program):
    expected = tool_json(program, "--scenario", "lift_one", "--model", "god_finger", "--hand", "fake")
    result = god_finger.run_experiment("lift_one", "god_finger", hand="fake")
    for name, value in result["metrics"].items():
        assert as_json(value) == expected["metrics"][name], name


def test_bad_options_raise_the_tools_messages():
    with pytest.raises(god_finger.Error, match="scenario 'rol' is not one of slide, lift_one"):
        god_finger.run_experiment("rol")
    with pytest.raises(ValueError, match="contact model 'point' is not one of god_object, god_finger, soft_finger"):
        god_finger.run_experiment("slide", "point")
    with pytest.raises(god_finger.Error, match=r"parameter 'push_height' = 0.5 is out of range \[0, 0.04\] \(m\)"):
        god_finger.run_experiment("slide", push_height=0.5)
    with pytest.raises(god_finger.Error, match="unknown parameter 'speed'"):
        god_finger.run_experiment("slide", speed=2)
    with pytest.raises(god_finger.Error, match="hand 'robot' is not one of ideal, fake"):
        god_finger.run_experiment("slide", hand="robot")
