#!/usr/bin/env python3
"""The method alone on a mesh file: press a finger on the highest point of a mesh with growing
force and draw its contact areas (the sub-god-objects walked over the surface), and the area's
radius against the force with the paper's Eq. 1.

    python3 examples/touch_mesh.py [MESH] [--out DIR]   # writes DIR/touch_mesh.png
MESH: any file load_mesh reads (default: the package's torus, urdf/meshes/torus.dae).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import god_finger  # noqa: E402

FORCES = [0.1, 0.25, 0.5, 1.0, 2.0, 4.0]  # N, pressing straight into the surface
STIFFNESS = 400.0  # N/m, the coupling's default
R_MAX, D0 = 0.01, 0.001  # m, the contact parameters' defaults (Eq. 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", nargs="?", default=god_finger.data_path("urdf", "meshes", "torus.dae"))
    parser.add_argument("--out", default=".", help="folder of the figure (default: here)")
    args = parser.parse_args()

    mesh = god_finger.load_mesh(args.mesh)
    top = mesh.vertices[np.argmax(mesh.vertices[:, 2])] + [0.0031, 0.0017, 0.0]  # beside the top vertex
    place = mesh.closest(top + [0.0, 0.0, 1.0])
    normal = place["normal"]
    areas = [god_finger.contact_area(mesh, place["point"], normal, force=-force * normal, stiffness=STIFFNESS,
                                     n_sgo=16)
             for force in FORCES]

    fig = plt.figure(figsize=(11, 4.8))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    centre = np.array(place["point"])
    near = [t for t in mesh.triangles if np.min(np.linalg.norm(mesh.vertices[t] - centre, axis=1)) < 0.025]
    ax.add_collection3d(Poly3DCollection([mesh.vertices[t] for t in near], facecolor=(0.8, 0.8, 0.85, 0.35),
                                         edgecolor=(0.4, 0.4, 0.5, 0.5), linewidth=0.3))
    for force, area in zip(FORCES, areas):
        ring = np.vstack([area.sub_god_objects, area.sub_god_objects[:1]])
        ax.plot(ring[:, 0], ring[:, 1], ring[:, 2], "o-", markersize=2.5, label="%.2g N: r %.1f mm" %
                (force, 1000 * area.radius))
    ax.scatter(*centre, color="k", s=12)
    ax.view_init(elev=60, azim=-60)
    span = 0.014
    ax.set_xlim(centre[0] - span, centre[0] + span)
    ax.set_ylim(centre[1] - span, centre[1] + span)
    ax.set_zlim(centre[2] - span, centre[2] + span)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("contact areas on %s" % os.path.basename(args.mesh))
    ax.legend(fontsize=7, loc="upper left")

    ax_r = fig.add_subplot(1, 2, 2)
    force = np.linspace(0.0, max(FORCES), 200)
    ax_r.plot(force, 1000 * R_MAX * (1 - np.exp(-force / STIFFNESS / D0)), label="Eq. 1: r_max (1 - exp(-s / D0'))")
    ax_r.plot(FORCES, [1000 * a.radius for a in areas], "o", label="contact_area")
    ax_r.set_xlabel("force pressing into the surface (N)")
    ax_r.set_ylabel("radius of the contact area (mm)")
    ax_r.grid(True, alpha=0.3)
    ax_r.legend()
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "touch_mesh.png")
    fig.savefig(path, dpi=100)
    for force, area in zip(FORCES, areas):
        print("%.2f N: r %.2f mm, %d sub-god-objects" % (force, 1000 * area.radius, len(area.sub_god_objects)))
    print("wrote", path)


if __name__ == "__main__":
    main()
