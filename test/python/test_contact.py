"""contact_area and load_mesh: the C++ call's result, on the package's own meshes."""
import os
import subprocess

import numpy as np
import pytest

import god_finger

MESHES = ["box.stl", "cylinder.ply", "l_block.off", "mug.obj", "sphere.obj", "torus.dae"]


@pytest.mark.parametrize("name", MESHES)
def test_contact_area_equals_the_cpp_call(program, root, name):
    path = os.path.join(root, "urdf", "meshes", name)
    out = subprocess.run([program("god_finger_contact_trace"), path, "200", "7"], check=True, capture_output=True,
                         text=True)
    mesh = god_finger.load_mesh(path)
    checked = 0
    for line in out.stdout.splitlines():
        numbers = [float(x) for x in line.split()]
        point, normal, coupling = numbers[1:4], numbers[4:7], numbers[7:10]
        depth, radius, count = numbers[10], numbers[11], int(numbers[12])
        positions = np.array(numbers[13:]).reshape(count, 3)
        area = god_finger.contact_area(mesh, point, normal, coupling, depth=depth)
        assert area.radius == radius
        assert area.positions.shape == (count, 3)
        np.testing.assert_array_equal(area.positions, positions)
        assert area.sub_god_objects.shape[0] == count - sum(area.dropped)
        checked += 1
    assert checked == 200


def test_an_area_on_a_flat_face():
    vertices = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], dtype=float) * 0.1
    mesh = god_finger.Mesh(vertices, [[0, 1, 2], [0, 2, 3]])
    assert mesh.vertices.shape == (4, 3) and mesh.triangles.shape == (2, 3)
    # Pressed straight down with 4 N on a 400 N/m coupling: s = 1 cm, r = r_max (1 - e^-10).
    area = god_finger.contact_area(mesh, [0.01, 0.02, 0.001], [0, 0, 1], force=[0, 0, -4.0], r_max=0.01, n_sgo=6)
    assert area.valid and area.feature == "face"
    np.testing.assert_allclose(area.point, [0.01, 0.02, 0.0], atol=1e-15)
    assert area.radius == pytest.approx(0.01 * (1 - np.exp(-10.0)), rel=1e-12)
    assert area.sub_god_objects.shape == (6, 3)
    np.testing.assert_allclose(np.linalg.norm(area.sub_god_objects - area.point, axis=1), area.radius, rtol=1e-9)
    assert all(stop == "distance_reached" for stop in area.stops)
    # A push along +x shortens the radial distances ahead and lengthens those behind (Eq. 2).
    pushed = god_finger.contact_area(mesh, [0.0, 0.0, 0.0], [0, 0, 1], [0.002, 0.0, -0.01], n_sgo=6)
    ahead = pushed.positions[:, 0] - pushed.point[0]
    assert pushed.target_distance[np.argmax(ahead)] < pushed.radius < pushed.target_distance[np.argmin(ahead)]


def test_closest_point_and_health(root):
    mesh = god_finger.load_mesh(os.path.join(root, "urdf", "meshes", "box.stl"))
    found = mesh.closest([0.0, 0.0, 10.0])
    assert found["distance"] > 9.0 and found["feature"] in ("face", "edge", "vertex")
    assert mesh.health["boundary_edges"] == 0 and mesh.health["components"] == 1
    assert "box.stl" in repr(mesh)
