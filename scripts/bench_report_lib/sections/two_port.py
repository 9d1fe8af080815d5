"""Section 13's second table: the channel's two ports observed, and the two-port controller
(delay_sweep.jsonl's rows with "passivity": "two_port"). Its credit is the passivity bound of
the target delay.lowest_energy (passivity_contact_credit is set to the same bound)."""
from ..common import table


def section(ctx, device_rows, two_port, keys, baseline, passive):
    text = ctx.prose("two_port")
    bound = passive.goal
    out = [text("intro"), ""]
    rows = []
    breaches = 0
    rung = 0
    for task, operator, round_trip in keys:
        if task == "free":
            continue
        key = (task, operator, round_trip)
        one = [t for t in device_rows if t["controller"] and (t["task"], t["operator"], t["round_trip_s"]) == key]
        two = [t for t in two_port if (t["task"], t["operator"], t["round_trip_s"]) == key]
        if not one or not two:
            continue
        base = baseline.get((task, operator), 0.0)
        felt = [t["felt_stiffness_N_per_m"] / base for t in two if base > 0.0]
        breaches += sum(1 for t in two if min(t["device_margin_J"], t["physics_margin_J"]) < bound)
        rung += sum(1 for t in two if t["sustained"])
        rows.append([task, operator, f"{1e3 * round_trip:.0f}",
                     *(f"{min(t[margin] for t in rows_of):+.2g}" for rows_of in (one, two)
                       for margin in ("device_margin_J", "physics_margin_J")),
                     f"{min(t['lowest_energy_J'] for t in two):+.2g}",
                     f"{sum(1 for t in two if t['sustained'])} of {len(two)}",
                     f"{1e3 * max(t['max_drift_m'] for t in two):.1f}",
                     f"{min(felt):.2f}-{max(felt):.2f}" if felt and task != "tap" else "-"])
    out += [table(["task", "operator", "round trip (ms)", "device port: device margin (J)",
                   "device port: physics margin (J)", "two-port: device margin (J)", "two-port: physics margin (J)",
                   "two-port: hand's lowest energy (J)", "two-port: sustained", "two-port: largest drift (mm)",
                   "two-port: stiffness felt / no link"], rows), ""]
    no_link = [t for t in two_port if t["round_trip_s"] == 0.0 and t["task"] != "free"]
    physics_held = sum(1 for t in two_port if t["task"] != "free" and t["physics_margin_J"] >= bound - 1e-12)
    contacts = [t for t in two_port if t["task"] != "free"]
    started = sum(1 for t in contacts if t["peak_force_N"] > 1.0)
    summary = text("held", credit=passive.goal_written, physics_held=physics_held, contacts=len(contacts),
                   both_held=len(contacts) - breaches, started=started)
    if no_link:
        summary += text("no_link", force=max(t["peak_force_N"] for t in no_link))
    out += [summary + text("rest", rung=rung), ""]
    return out
