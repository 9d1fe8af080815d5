"""## 13. Across a delayed link: the delay sweep (delay_sweep.jsonl, bench/delay_sweep_bench.cpp).
The first table and the targets are the package's controller, at the device's port; the
two-port form's rows have a table of their own (two_port.py). Passive means the lowest energy at
or above the goal of the target delay.lowest_energy."""
from ..common import load_jsonl, table
from . import two_port

FILE = "delay_sweep.jsonl"


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("delay")
    passive = ctx.targets.get("delay.lowest_energy")
    sustained = ctx.targets.get("delay.sustained")
    trials = load_jsonl(ctx.path(FILE))
    commit = trials[0].get("commit", "") if trials else ""
    out = [text("heading"), "",
           text("intro", measured_at=text("measured_at", commit=commit) if commit else ""), "",
           text("columns", passive=passive.goal_column()), ""]
    two_port_trials = [t for t in trials if t.get("passivity", "device_port") == "two_port"]
    trials = [t for t in trials if t.get("passivity", "device_port") == "device_port"]
    baseline = {}
    for t in trials:
        if t["round_trip_s"] == 0.0 and t["controller"]:
            baseline[(t["task"], t["operator"])] = t["felt_stiffness_N_per_m"]
    keys = []
    for t in trials:
        key = (t["task"], t["operator"], t["round_trip_s"])
        if key not in keys and t["round_trip_s"] > 0.0:
            keys.append(key)
    rows = []
    worst_on = 0.0
    sustained_on = 0
    settings_on = 0
    for task, operator, round_trip in keys:
        group = [t for t in trials if (t["task"], t["operator"], t["round_trip_s"]) == (task, operator, round_trip)]
        off = [t for t in group if not t["controller"]]
        on = [t for t in group if t["controller"]]
        base = baseline.get((task, operator), 0.0)
        felt = [t["felt_stiffness_N_per_m"] / base for t in on if base > 0.0]
        lowest_on = min(t["lowest_energy_J"] for t in on)
        worst_on = min(worst_on, lowest_on)
        sustained_on += sum(1 for t in on if t["sustained"])
        settings_on += len(on)
        rows.append([task, operator, f"{1e3 * round_trip:.0f}",
                     f"{min(t['lowest_energy_J'] for t in off):+.3g}",
                     f"{sum(1 for t in off if t['sustained'])} of {len(off)}",
                     f"{lowest_on:+.2g}", f"{sum(1 for t in on if t['sustained'])} of {len(on)}",
                     f"{max(t['peak_force_N'] for t in on):.2f}",
                     f"{min(felt):.2f}-{max(felt):.2f}" if felt else "-"])
    out += [table(["task", "operator", "round trip (ms)", "off: lowest energy (J)", "off: sustained",
                   "on: lowest energy (J)", "on: sustained", "on: peak force (N)", "on: stiffness felt / no link"],
                  rows), ""]
    failing = [(t["task"], t["operator"], t["round_trip_s"]) for t in trials
               if t["controller"] and not passive.met(t["lowest_energy_J"])]
    reach = sorted({rt for _, _, rt in keys if all(k[2] != rt for k in failing)})
    out += [_summary(text, trials, keys, reach, worst_on, passive), ""]
    if two_port_trials:
        out += two_port.section(ctx, trials, two_port_trials, keys, baseline, passive)
    note = text("met_up_to", reach_ms=1e3 * max(reach)) if reach else None
    ctx.targets.checked(passive, worst_on, passive.spread, passive.plain_verdict(worst_on, note),
                        detail=text("worst_of", count=settings_on))
    ctx.targets.checked(sustained, sustained_on, sustained.spread, sustained.plain_verdict(sustained_on),
                        detail=text("of_settings", count=settings_on))
    return out


def _summary(text, trials, keys, reach, worst_on, passive):
    """How far the controller keeps every setting passive, and what the tremor does through the
    shortest link (pressing and grasping, where the hand rests on a contact; further round trips
    still ring down from the first contact in that window)."""
    shortest = min((rt for _, _, rt in keys), default=0.0)
    gains = [t["tremor_hf_rms_N"] / t["baseline_tremor_hf_rms_N"] for t in trials
             if t["operator"] == "human_like" and t["task"] in ("press", "grasp") and t["round_trip_s"] == shortest
             and t.get("baseline_tremor_hf_rms_N", 0.0) > 0.0]
    # Whether the human-like settings at that round trip die once the hand is still (not sustained).
    tremor_dies = all(not t["sustained"] for t in trials
                      if t["operator"] == "human_like" and t["round_trip_s"] == shortest)
    summary = text("reach", reach_ms=1e3 * max(reach)) if reach else text("no_reach")
    summary += text("worst", worst=worst_on) + (text("cut") if passive.met(worst_on) else text("capped"))
    summary += text("controller_off")
    if gains:
        summary += text("tremor", low=min(gains), high=max(gains), round_trip_ms=1e3 * shortest,
                        fate=text("tremor_dies") if tremor_dies else text("tremor_rings"))
    return summary + text("forces", limit=max(t["max_force_N"] for t in trials))
