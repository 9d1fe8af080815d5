"""## 2. Speed against error: the walk surface (walk_accuracy.json)."""
import matplotlib.pyplot as plt

from ..common import load_benchmarks, match, table

FILE = "walk_accuracy.json"


def section(ctx):
    names = ctx.names(FILE)
    text = ctx.prose("walk")
    results = load_benchmarks(ctx.path(FILE))
    out = [text("heading"), "", text("command")]
    rows = []
    plt.figure(figsize=(6.4, 4))
    for surface in names["surfaces"]:
        shape, key = surface["label"], surface["resolution"]
        for walk, label in enumerate(names["walks"]):
            points = []
            for name, (time_ns, counters, _) in results.items():
                fields = match(surface["benchmark"], name)
                if fields and fields["walk"] == walk:
                    points.append((counters["triangles"], time_ns / 1e3, counters["error_um"], fields[key]))
            points.sort()
            for triangles, us, error, resolution in points:
                rows.append([shape, f"{key} {resolution}", f"{triangles:,.0f}", label, f"{us:.2f}", f"{error:.2f}"])
            plt.loglog([p[1] for p in points], [p[2] for p in points], "o-" if walk else "s--",
                       label=f"{shape}, {label}")
        exact = results.get(surface["exact"])
        if exact is not None:
            time_ns, counters, _ = exact
            rows.append([shape, "exact", "none", "exact", f"{time_ns / 1e3:.2f}", f"{counters['error_um']:.2g}"])
            plt.loglog([time_ns / 1e3], [max(counters["error_um"], 1e-6)], "k*", markersize=12,
                       label=f"{shape}, exact (error shown at 1e-6 um if below)")
    plt.xlabel("time per contact (us)")
    plt.ylabel("sub-god-object error (um)")
    plt.legend(fontsize=8)
    plt.grid(True, which="both", alpha=0.3)
    out += ["", table(["surface", "resolution", "triangles", "walk", "time (us)", "error (um)"], rows), ""]
    out += [ctx.figures.save("walk_error_vs_cost.png"), ""]
    return out
