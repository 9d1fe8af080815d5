"""## 14. The ROS drivers labs run: state to force through each driver bridge
(ros_drivers.jsonl, bench/ros_driver_latency.cpp), against roscpp's own round trip (the floor)."""
import sys

from ..common import Measure, load_jsonl, table
from ..targets import value_at

FILE = "ros_drivers.jsonl"


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("drivers")
    floor = ctx.names(FILE)["floor"]
    runs = load_jsonl(ctx.path(FILE))
    commit = runs[0].get("commit", "") if runs else ""
    out = [text("heading"), "", text("command", measured_at=text("measured_at", commit=commit) if commit else ""), ""]
    targets = ctx.targets.in_section("drivers")
    rows = []
    drivers = []
    for run in runs:
        if run["driver"] not in drivers:
            drivers.append(run["driver"])
    for driver in drivers:
        mine = [r for r in runs if r["driver"] == driver]
        p50 = sorted(r["latency_us_p50"] for r in mine)
        p99 = sorted(r["latency_us_p99"] for r in mine)
        rows.append([text("floor") if driver == floor else driver, str(len(mine)),
                     f"{sum(r['answered'] for r in mine)} / {sum(r['steps'] for r in mine)}",
                     f"{p50[len(p50) // 2]:.0f} ({p50[0]:.0f}-{p50[-1]:.0f})",
                     f"{p99[len(p99) // 2]:.0f} ({p99[0]:.0f}-{p99[-1]:.0f})",
                     f"{max(r['latency_us_max'] for r in mine):.0f}",
                     f"{min(r['state_rate_hz'] for r in mine):.0f}"])
        if driver != floor and not any(target.matches(mine[0]) for target in targets):
            print(text("no_target", file=FILE, driver=driver), file=sys.stderr)
    for target in targets:
        # Over the rounds: the median and the range of each round's p99, in ms.
        values = sorted(value_at(r, target.key) for r in target.records(runs))
        if values:
            ctx.targets.measured(target, Measure(values[len(values) // 2] * 1e-3, values[0] * 1e-3, values[-1] * 1e-3,
                                                 text("rounds", count=len(values))))
    out += [table(["driver", "rounds", "steps answered", "p50 us (rounds' range)", "p99 us (rounds' range)",
                   "max us", "states/s"], rows), ""]
    return out
