"""## 11. Real objects (real_objects.json): loads, steps and one contact area on real-style meshes
against the paper's box scene."""
from .. import benchmark_targets
from ..common import load_benchmarks, load_json, table

FILE = "real_objects.json"


def section(ctx):
    if not ctx.has(FILE):
        return []
    names = ctx.names(FILE)
    text = ctx.prose("real_objects")
    path = ctx.path(FILE)
    results = load_benchmarks(path)
    out = [text("heading"), "", text("command"), ""]
    commit = load_json(path).get("context", {}).get("commit")
    if commit:
        out += [text("commit", commit=commit), ""]
    objects = names["objects"]
    rows = []
    for index, name in enumerate(objects):
        first = results.get(names["load"].format(object=index, cached=0))
        cached = results.get(names["load"].format(object=index, cached=1))
        if not first or not cached:
            continue
        rows.append([name, f"{first[1].get('triangles', 0):.0f}", f"{first[0] / 1e6:.0f}", f"{cached[0] / 1e6:.1f}"])
    out.append(table(["object", "triangles", "first load (ms)", "cached load (ms)"], rows))
    out.append("")
    rows = []
    for index, name in enumerate(objects):
        for fingers in names["fingers"]:
            finger = results.get(names["step"].format(object=index, fingers=fingers, god_object=0))
            point = results.get(names["step"].format(object=index, fingers=fingers, god_object=1))
            if not finger or not point:
                continue
            counters = finger[1]
            rows.append([name, str(fingers), f"{counters['p50_us']:.1f}", f"{counters['p99_us']:.1f}",
                         f"{point[1]['p50_us']:.1f}", f"{point[1]['p99_us']:.1f}",
                         "-" if name == names["primitive"] else f"{counters['pad_error_um'] * 1e3:.3g}",
                         f"{counters['touching']:.2f}"])
    out.append(table(["object", "fingers", "god_finger p50 (us)", "p99 (us)", "god_object p50 (us)", "p99 (us)",
                      "pad off the surface, largest (nm)", "areas per step"], rows))
    out.append("")
    rows = []
    for index, name in enumerate(objects):
        area = results.get(names["contact_area"].format(object=index))
        if area:
            rows.append([name, f"{area[1].get('triangles', 0):.0f}", f"{area[0] / 1e3:.2f}"])
    out += [text("contact_area"), "", table(["object", "triangles", "time (us)"], rows), ""]
    benchmark_targets.measure_section(ctx, "real_objects")
    return out
