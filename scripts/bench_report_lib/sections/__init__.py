"""The report's sections in their order, one module each: `section(ctx)` returns its Markdown
lines (none when its raw file is absent) and records its targets' rows in ctx.targets.
delay's second table (two_port) and operator's hand tasks (operator_hand, operator_oriented)
are parts of their sections."""
from . import (contact, delay, drivers, hand, haptic, mujoco, operator, pad_fidelity, physics, python, real_objects,
               scale, scene_load, sim, soft, walk)

ORDER = [contact, walk, physics, sim, haptic, hand, pad_fidelity, mujoco, scale, scene_load, operator, real_objects,
         soft, delay, drivers, python]
# The names bench/targets.yaml's `section` field takes.
NAMES = [module.__name__.rsplit(".", 1)[1] for module in ORDER]
