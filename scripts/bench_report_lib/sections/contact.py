"""## 1. One contact: god-object location against god-finger contact area (contact_area.json)."""
import matplotlib.pyplot as plt

from .. import benchmark_targets
from ..common import load_benchmarks, match, table

FILE = "contact_area.json"


def section(ctx):
    names = ctx.names(FILE)
    text = ctx.prose("contact")
    results = load_benchmarks(ctx.path(FILE))
    pad = names["plate_pad"]
    out = [text("heading"), "", text("command")]
    # The plates (mesh:-N), smallest first.
    plates = sorted((fields["mesh"], name) for name, fields in
                    ((name, match(names["locate"], name)) for name in results) if fields and fields["mesh"] < 0)
    rows, sizes, locate, area, total = [], [], [], [], []
    for mesh, name in plates:
        time_ns, counters, _ = results[name]
        finger = results.get(names["contact"].format(mesh=mesh, **pad))
        only = results.get(names["area"].format(mesh=mesh, **pad))
        if not finger or not only:
            continue
        triangles = counters["triangles"]
        sizes.append(triangles)
        locate.append(time_ns / 1e3)
        area.append(only[0] / 1e3)
        total.append(finger[0] / 1e3)
        rows.append([f"{triangles:,.0f}", f"{time_ns / 1e3:.2f}", f"{only[0] / 1e3:.2f}", f"{finger[0] / 1e3:.2f}",
                     f"{finger[1]['sgo_active']:.1f}", f"{counters['bytes_per_triangle']:.1f}"])
    order = sorted(range(len(sizes)), key=lambda i: sizes[i])
    rows = [rows[i] for i in order]
    out += ["", table(["triangles", "god-object: locate (us)", "contact area alone (us)",
                       "god-finger: locate + area (us)", "sub-god-objects", "bytes / triangle"], rows), ""]
    plt.figure(figsize=(6, 3.6))
    xs = [sizes[i] for i in order]
    plt.loglog(xs, [locate[i] for i in order], "o-", label="god-object: locate")
    plt.loglog(xs, [area[i] for i in order], "s-", label="contact area alone")
    plt.loglog(xs, [total[i] for i in order], "^-", label="god-finger: locate + area")
    plt.xlabel("mesh triangles (2 mm cells)")
    plt.ylabel("time per contact (us)")
    plt.legend()
    plt.grid(True, which="both", alpha=0.3)
    out += [ctx.figures.save("contact_cost_vs_mesh_size.png"), ""]
    if area:
        out.append(text("flat", spread=max(area) / min(area), low=min(locate), high=max(locate)))
    benchmark_targets.measure_section(ctx, "contact")
    out += _n_sgo_sweep(ctx, names, text, results, pad)
    return out


def _n_sgo_sweep(ctx, names, text, results, pad):
    """The time against n_SGO on the ball, for both walks (walk:0 project, walk:1 unfold)."""
    ball = names["ball_mesh"]
    series = {0: ([], []), 1: ([], [])}
    for name, (time_ns, _, _) in results.items():
        fields = match(names["contact"], name)
        if fields and fields["mesh"] == ball:
            series[fields["walk"]][0].append(fields["n_sgo"])
            series[fields["walk"]][1].append(time_ns / 1e3)
    rows = []
    for n in sorted(set(series[0][0]) | set(series[1][0])):
        row = [n]
        for walk in (0, 1):
            values = dict(zip(*series[walk]))
            row.append(f"{values[n]:.2f}" if n in values else "")
        rows.append(row)
    area = results.get(names["area"].format(mesh=ball, **pad))
    per_walk = ""
    if area and area[1].get("crossings", 0.0) > 0:
        # The counter is per contact area: one walk per sub-god-object.
        per_walk = text("per_walk", crossings=area[1]["crossings"] / pad["n_sgo"], n_sgo=pad["n_sgo"])
    out = ["", text("sweep", per_walk=per_walk), ""]
    out.append(table(["n_SGO", "project walk (us)", "unfold walk (us)"], rows))
    locate = results.get(names["locate"].format(mesh=ball))
    if locate:
        out.append("\n" + text("ball_locate", us=locate[0] / 1e3))
    plt.figure(figsize=(6, 3.6))
    for walk, label in ((0, "project (the paper)"), (1, "unfold")):
        pairs = sorted(zip(*series[walk]))
        plt.plot([p[0] for p in pairs], [p[1] for p in pairs], "o-", label=label)
    plt.xlabel("n_SGO")
    plt.ylabel("time per contact (us)")
    plt.legend()
    plt.grid(True, alpha=0.3)
    out += ["", ctx.figures.save("contact_cost_vs_n_sgo.png"), ""]
    return out
