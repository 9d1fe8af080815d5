"""The Python code of the README and docs/python.md runs as written, from the checkout's root."""
import os
import re
import runpy

import pytest


def python_blocks(path):
    with open(path) as handle:
        return re.findall(r"```python\n(.*?)```", handle.read(), re.S)


@pytest.mark.parametrize("page", ["README.md", "docs/python.md"])
def test_the_pages_code_runs(root, page, monkeypatch, tmp_path, capsys):
    blocks = python_blocks(os.path.join(root, page))
    assert blocks, page + " has no python block"
    monkeypatch.chdir(root)
    for number, block in enumerate(blocks):
        script = tmp_path / ("block%d.py" % number)
        script.write_text(block)
        runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out
    assert "(8, 3)" in printed or "(12, 3)" in printed


# --- What the docs state, read from the code and the generated results ---------------------------
# The tests below need nothing built: they read the pages, the sources, the launch files and the
# committed results. Each runs its check on an edited copy too, to show that it fails.

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read(relative):
    with open(os.path.join(ROOT, relative)) as handle:
        return handle.read()


def doc_pages():
    """{page: text} of the README and every page of docs/."""
    pages = {"README.md": read("README.md")}
    for name in sorted(os.listdir(os.path.join(ROOT, "docs"))):
        if name.endswith(".md"):
            pages["docs/" + name] = read("docs/" + name)
    return pages


def launch_comments():
    """{launch/NAME.launch: its comments' text}: the launch files say what they do in comments."""
    folder = os.path.join(ROOT, "launch")
    return {"launch/" + name: "\n".join(re.findall(r"<!--(.*?)-->", read("launch/" + name), re.S))
            for name in sorted(os.listdir(folder)) if name.endswith(".launch")}


# Colours: the RGB the code gives a marker, and the name a reader would give it.

def colour_name(rgb):
    """The name of an RGB colour in [0, 1] by its hue ("light" when pale)."""
    r, g, b = rgb
    high, low = max(rgb), min(rgb)
    if high - low < 0.15:
        return "white" if high > 0.8 else "grey"
    if high == r:
        hue = (60 * (g - b) / (high - low)) % 360
    elif high == g:
        hue = 60 * (2 + (b - r) / (high - low))
    else:
        hue = 60 * (4 + (r - g) / (high - low))
    for limit, name in ((15, "red"), (45, "orange"), (70, "yellow"), (160, "green"), (200, "cyan"), (260, "blue"),
                        (290, "purple"), (345, "magenta"), (360, "red")):
        if hue < limit:
            return name


def test_colour_name():
    assert colour_name((0.9, 0.2, 0.9)) == "magenta"
    assert colour_name((0.2, 0.9, 0.2)) == "green"
    assert colour_name((1.0, 0.9, 0.0)) == "yellow"
    assert colour_name((0.1, 0.3, 1.0)) == "blue"
    assert colour_name((1.0, 0.5, 0.0)) == "orange"
    assert colour_name((0.0, 0.85, 1.0)) == "cyan"
    assert colour_name((1.0, 0.2, 0.2)) == "red"


def number(text):
    return float(text.rstrip("f"))


def member_colour(source, variable):
    """`variable.color.r = 0.9f;` and `stem.color.r = stem.color.b = 0.2f;` in `source`."""
    rgb = {}
    for chain, value in re.findall(rf"((?:\b{variable}\.color\.[rgb]\s*=\s*)+)([0-9.]+f?)\s*;", source):
        for channel in re.findall(r"color\.([rgb])", chain):
            rgb[channel] = number(value)
    assert set(rgb) == set("rgb"), f"{variable}'s colour not found: {rgb}"
    return rgb["r"], rgb["g"], rgb["b"]


def set_colour(source, variable):
    """`setColor(&variable, r, g, b[, a])` in `source`."""
    match = re.search(rf"setColor\(&{variable},\s*([0-9.]+f?),\s*([0-9.]+f?),\s*([0-9.]+f?)", source)
    assert match, f"setColor(&{variable}, ...) not found"
    return tuple(number(value) for value in match.groups())


def finger_palette(source):
    """fingerColour()'s palette, interface 0 first."""
    body = re.search(r"FingerColour fingerColour\(int interface\)\s*\{(.*?)\n\}", source, re.S).group(1)
    return [tuple(number(v) for v in triple)
            for triple in re.findall(r"\{\s*([0-9.]+f?),\s*([0-9.]+f?),\s*([0-9.]+f?)\s*\}", body)]


def code_colours():
    """{thing: colour name} of what rviz shows, from src/ros."""
    handle = read("src/ros/hand_marker.cpp")
    markers = read("src/ros/markers.cpp")
    palette = finger_palette(markers)
    assert len(palette) >= 5, palette
    return {
        "the interactive handle": colour_name(member_colour(handle, "ball")),
        "the handle's stem": colour_name(member_colour(handle, "stem")),
        "a god-object": colour_name(set_colour(markers, "proxy")),
        "the force on the hand": colour_name(set_colour(markers, "force")),
        "a sub-god-object": colour_name(set_colour(markers, "sgos")),
        "an interface point": colour_name(set_colour(markers, "device")),
        "a fingertip's nail": colour_name(set_colour(markers, "nail")),
        "the first finger's contact area": colour_name(palette[0]),
        "the finger palette": [colour_name(rgb) for rgb in palette],
    }


COLOUR = r"(red|orange|yellow|green|cyan|blue|purple|violet|magenta|pink|white|grey|gray)"
# How the pages name each thing's colour (case aside).
COLOUR_CLAIMS = {
    "the interactive handle": [rf"\b{COLOUR} (?:ball|sphere) is the handle", rf"drag the {COLOUR} (?:sphere|ball|handle)",
                               rf"the handle \({COLOUR}\)", rf"\b{COLOUR} handle\b"],
    "the handle's stem": [rf"\b{COLOUR} stem\b"],
    "a god-object": [rf"god-objects? \({COLOUR}\)", rf"\({COLOUR}\s+god-object", rf"\b{COLOUR}\s+proxies\b"],
    "the force on the hand": [rf"\b{COLOUR}: force on the hand", rf"force on the hand \({COLOUR}\)",
                              rf"\b{COLOUR}\s+force arrows?"],
    "a sub-god-object": [rf"\b{COLOUR}\s+sub-god-objects?", rf"sub-god-objects? \({COLOUR}\)"],
    "an interface point": [rf"\({COLOUR}\s+points\b"],
    "a fingertip's nail": [rf"\b{COLOUR}\s+nail\b"],
    "the first finger's contact area": [rf"contact area \({COLOUR}\)", rf"\bits {COLOUR} area\b",
                                        rf"contact area (?:in )?{COLOUR}\b", rf"in its own colour \(the\s+first {COLOUR}\)"],
}


def colour_problems(pages):
    """Every colour a page names for a marker that differs from the code's, and the claims found."""
    colours = code_colours()
    problems, found = [], []
    for page, text in pages.items():
        flat = re.sub(r"\s+", " ", text)
        for thing, patterns in COLOUR_CLAIMS.items():
            for pattern in patterns:
                for match in re.finditer(pattern, flat, re.I):
                    said = match.group(1).lower().replace("gray", "grey")
                    found.append((page, thing))
                    if said != colours[thing]:
                        problems.append(f"{page}: \"{match.group(0)}\": the code makes {thing} {colours[thing]}, not {said}")
        # The fingers' colours in order: "yellow, cyan, magenta, green, orange".
        for match in re.finditer(rf"\b{COLOUR}(?:, {COLOUR}){{2,}}\b", flat, re.I):
            said = [name.lower() for name in re.split(r", ", match.group(0))]
            found.append((page, "the finger palette"))
            if said != colours["the finger palette"][:len(said)]:
                problems.append(f"{page}: \"{match.group(0)}\": the fingers' palette is "
                                f"{', '.join(colours['the finger palette'][:len(said)])}")
    return problems, found


def test_the_colours_the_docs_name_are_the_codes():
    problems, found = colour_problems(doc_pages())
    assert not problems, "\n".join(problems)
    # The claims this test exists for are still found (a page reworded past the patterns says so here).
    assert ("docs/devices.md", "the interactive handle") in found, found
    assert ("docs/demo.md", "the interactive handle") in found, found
    assert ("docs/devices.md", "the finger palette") in found, found
    assert len(found) >= 10, found


def test_a_wrong_colour_in_a_page_fails():
    pages = doc_pages()
    pages["docs/devices.md"] = pages["docs/devices.md"].replace("drag the magenta sphere", "drag the green sphere")
    pages["README.md"] = pages["README.md"].replace("god-object (blue)", "god-object (red)")
    pages["docs/demo.md"] = pages["docs/demo.md"].replace("green stem", "blue stem")
    problems, _ = colour_problems(pages)
    assert any("drag the green sphere" in problem and "magenta" in problem for problem in problems), problems
    assert any("README.md" in problem and "god-object (red)" in problem for problem in problems), problems
    assert any("blue stem" in problem for problem in problems), problems


# Launch commands: every argument a page gives a launch file is one the file declares, and an
# argument that acts only under another (record_bag under record:=true) comes with it.

LAUNCH_COMMAND = re.compile(r"(?:roslaunch\s+([\w-]+)\s+)?\b([\w-]+)\.launch\b((?:[ \t]+[A-Za-z]\w*:=[^\s`'\")\],;]*)+)?")
ARGUMENT = re.compile(r"\b([A-Za-z]\w*):=([^\s`'\")\],;]*)")


def launch_tree(name):
    import xml.etree.ElementTree as ElementTree
    return ElementTree.parse(os.path.join(ROOT, "launch", name + ".launch")).getroot()


def declared(name):
    """{argument: its default (None: none, or an expression)} of launch/NAME.launch."""
    out = {}
    for element in launch_tree(name).findall("arg"):
        value = element.get("default", element.get("value"))
        out[element.get("name")] = value if value in ("true", "false") else None
    return out


def conditions(launch, argument, seen=frozenset()):
    """What every use of `argument` in launch/LAUNCH.launch sits under: {(other argument, true or
    false)}, the conditions of `if="$(arg X)"` and `unless="$(arg X)"` common to all its uses,
    through the launch files it includes and the arguments it sets. Empty: some use acts always
    (or under a condition this reading does not follow)."""
    if (launch, argument) in seen:
        return set()
    seen = seen | {(launch, argument)}
    root = launch_tree(launch)
    parents = {child: parent for parent in root.iter() for child in parent}
    use = re.compile(rf"\$\(arg {re.escape(argument)}\)|\$\(eval [^)]*\b{re.escape(argument)}\b")
    common = None
    for element in root.iter():
        if element.tag == "arg" and element.get("name") == argument and parents.get(element) is root:
            continue  # its own declaration
        if not any(use.search(value) for value in element.attrib.values()):
            continue
        found, node = set(), element
        while node is not None:
            for key, want in (("if", True), ("unless", False)):
                gate = re.fullmatch(r"\$\(arg (\w+)\)", node.get(key, ""))
                if gate:
                    found.add((gate.group(1), want))
            node = parents.get(node)
        parent = parents.get(element)
        if element.tag == "arg" and parent is root:
            found |= conditions(launch, element.get("name"), seen)  # another argument defined from it
        elif element.tag == "arg" and parent is not None and parent.tag == "include":
            included = re.fullmatch(r"\$\(find god_finger\)/launch/([\w-]+)\.launch", parent.get("file", ""))
            if included:
                passed = {a.get("name"): a.get("value") for a in parent.iter("arg")}
                inner_defaults = declared(included.group(1))
                dead = False
                for gate, want in conditions(included.group(1), element.get("name"), seen):
                    value = passed.get(gate, inner_defaults.get(gate))
                    outer = re.fullmatch(r"\$\(arg (\w+)\)", value or "")
                    if outer:
                        found.add((outer.group(1), want))
                    elif value in ("true", "false") and (value == "true") != want:
                        dead = True  # never acts through this include
                if dead:
                    continue
        found.discard((argument, True))
        found.discard((argument, False))
        common = found if common is None else common & found
    return common or set()


def launch_problems(pages):
    """Every launch argument a page uses that its launch file does not declare, or uses without
    the argument it acts under."""
    launches = sorted(name[:-len(".launch")] for name in os.listdir(os.path.join(ROOT, "launch")) if name.endswith(".launch"))
    arguments = {name: declared(name) for name in launches}
    problems, commands = [], 0

    def check(page, text, candidates, given):
        """`given` ({argument: value}) is right for one of the candidate launch files."""
        why = []
        for launch in candidates:
            unknown = [a for a in given if a not in arguments[launch]]
            if unknown:
                why.append(f"{launch}.launch declares no {', '.join(unknown)}")
                continue
            for argument in given:
                for gate, want in sorted(conditions(launch, argument)):
                    value = given.get(gate, arguments[launch].get(gate))
                    if value in ("true", "false") and (value == "true") != want:
                        why.append(f"{launch}.launch: {argument} acts only with {gate}:={str(want).lower()}")
            if not why:
                return
        problems.append(f"{page}: \"{text.strip()}\": {'; '.join(why) or 'no launch file declares these arguments'}")

    for page, text in pages.items():
        spans = []
        for match in LAUNCH_COMMAND.finditer(text):
            package, launch = match.group(1), match.group(2)
            spans.append(match.span())
            if package not in (None, "god_finger"):
                continue
            if launch not in arguments:
                if package == "god_finger":
                    problems.append(f"{page}: \"{match.group(0).strip()}\": there is no launch/{launch}.launch")
                continue
            commands += 1
            check(page, match.group(0), [launch], dict(ARGUMENT.findall(match.group(3) or "")))
        # Arguments named without their launch file (`record:=true record_bag:=...`): right for some launch file.
        for match in re.finditer(r"`([^`\n]*:=[^`\n]*)`", text):
            if any(start <= match.start() < end or start < match.end() <= end for start, end in spans):
                continue
            if re.search(r"\b(rosrun|rosparam|rosservice|rostopic|roslaunch|rqt\w*)\b", match.group(1)):
                continue
            if text[max(0, match.start() - 20):match.start()].endswith("driver's "):
                continue  # an argument of the vendor driver's own launch file
            given = dict(ARGUMENT.findall(match.group(1)))
            if given:
                commands += 1
                check(page, match.group(0), [name for name in launches if set(given) <= set(arguments[name])] or launches[:1],
                      given)
    return problems, commands


def test_the_launch_commands_in_the_docs_use_declared_arguments():
    problems, commands = launch_problems({**doc_pages(), **launch_comments()})
    assert not problems, "\n".join(problems)
    assert commands >= 40, commands


def test_record_bag_acts_only_with_record():
    assert conditions("demo", "record_bag") == {("record", True)}
    assert conditions("demo", "bag") == set()  # also the replay's bag


def test_a_wrong_launch_command_in_a_page_fails():
    pages = {"docs/a.md": "```bash\nroslaunch god_finger demo.launch rviz:=true recrod:=true\n```\n"
                          "Or `record_bag:=/tmp/replayed.bag` records the replay, "
                          "and `roslaunch god_finger demos.launch` runs nothing.\n",
             "docs/b.md": "`record:=true record_bag:=/tmp/replayed.bag` records the replay.\n"}
    problems, _ = launch_problems(pages)
    assert any("recrod" in problem and "declares no recrod" in problem for problem in problems), problems
    assert any("`record_bag:=/tmp/replayed.bag`" in problem and "record:=true" in problem for problem in problems), problems
    assert any("no launch/demos.launch" in problem for problem in problems), problems
    assert not any("docs/b.md" in problem for problem in problems), problems


# The door: how far it opens, the script's arc and the hinge's limit, as the docs state them,
# against the experiment's committed output (docs/experiments.md's generated table, which
# readme_figures_test regenerates from god_finger_experiment), the script and the scene.

def door_figures():
    import math
    block = re.search(r"<!-- generated: experiments\b.*?<!-- end generated: experiments -->",
                      read("docs/experiments.md"), re.S).group(0)
    opened = [float(value) for value in re.findall(r"^\| door \| \w+ \|[^|]*\bopened_rad ([0-9.]+)", block, re.M)]
    assert len(opened) >= 3, "docs/experiments.md's generated table lacks the door's opened_rad"
    script = [row for row in re.findall(r"^\s*- \[([^\]]*)\]", read("config/scripts/door.yaml"), re.M)]
    first, last = ([float(v) for v in row.split(",")] for row in (script[1], script[-1]))
    # The script's arc about the hinge (at the origin): from where the finger meets the face to its end.
    arc = math.degrees(math.atan2(last[2], last[1]) - math.atan2(first[2], first[1]))
    limit = float(re.search(r'<joint name="hinge".*?<limit [^>]*upper="([0-9.]+)"', read("urdf/scenes/door.urdf"), re.S).group(1))
    return {"opened": [math.degrees(value) for value in opened], "arc": arc, "limit": math.degrees(limit)}


def door_problems(pages):
    figures = door_figures()
    low, high = min(figures["opened"]) - 1.0, max(figures["opened"]) + 1.0  # opened_rad has 3 figures
    problems, found = [], 0
    for page, text in pages.items():
        # The sentences of the paragraphs and list items that speak of the door.
        paragraphs = [p for p in re.split(r"\n\s*\n|\n(?=\s*- )", text) if "door" in p or "door" in page]
        for sentence in (s for p in paragraphs for s in re.split(r"(?<=[.;])\s+", re.sub(r"\s+", " ", p))):
            for match in re.finditer(r"\bopen\w*(?: the door| it)?\s+(about |to |past |by )?(\d+(?:\.\d+)?) degrees", sentence):
                if "handle" in sentence:
                    continue  # a push by hand, with the interactive handle: as far as the user drags
                found += 1
                said = float(match.group(2))
                if (match.group(1) == "past " and said >= low) or (match.group(1) != "past " and not low <= said <= high):
                    opened = sorted({f"{value:.1f}" for value in figures["opened"]})
                    problems.append(f"{page}: \"{match.group(0)}\": the experiment opens it {' to '.join(opened)} degrees "
                                    "(opened_rad, docs/experiments.md)")
            for match in re.finditer(r"\b(?:arc (?:to|stops at)|script's) (\d+) degrees", sentence):
                found += 1
                if abs(float(match.group(1)) - figures["arc"]) > 0.5:
                    problems.append(f"{page}: \"{match.group(0)}\": the script's arc (config/scripts/door.yaml) ends at "
                                    f"{figures['arc']:.1f} degrees")
                if re.search(r"past the script's", match.group(0) + sentence) and figures["arc"] >= low:
                    problems.append(f"{page}: \"{sentence}\": the door opens no further than the script's arc")
            for match in re.finditer(r"hinge \(0 to (\d+) degrees", sentence):
                found += 1
                if abs(float(match.group(1)) - figures["limit"]) > 1.0:
                    problems.append(f"{page}: \"{match.group(0)}\": door.urdf's limit is {figures['limit']:.0f} degrees")
    return problems, found


def test_the_door_angles_the_docs_state_are_the_experiments():
    problems, found = door_problems({**doc_pages(), **launch_comments()})
    assert not problems, "\n".join(problems)
    assert found >= 3, found


def test_a_wrong_door_angle_fails():
    pages = {"docs/demo.md": "The fake finger pushes the door open 60 degrees.",
             "docs/x.md": "door: every model opens the door about 75 degrees, past the script's 65 degrees.",
             "launch/door.launch": "A finger pushes a cabinet door open, along an arc to 60 degrees.",
             "docs/experiments.md": "a door on a vertical hinge (0 to 90 degrees, damping 0.05 N m s/rad)."}
    problems, _ = door_problems(pages)
    assert any("open 60 degrees" in problem for problem in problems), problems
    assert any("opens the door about 75 degrees" in problem for problem in problems), problems
    assert any("arc to 60 degrees" in problem for problem in problems), problems
    assert any("0 to 90 degrees" in problem for problem in problems), problems


# Short and true: the README's status rows are short and point at their detail in docs/status.md;
# the user docs tell what is true now, not the project's history; the tests they name exist.

def table_rows(text, heading):
    section = re.search(rf"^## {re.escape(heading)}\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    assert section, heading
    return [line for line in section.group(1).splitlines() if line.startswith("|") and not line.startswith("|---")][1:]


def github_anchor(heading):
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def status_problems(readme, status):
    problems = []
    rows = table_rows(readme, "Status")
    anchors = {github_anchor(h) for h in re.findall(r"^#+ (.*)$", status, re.M)}
    for row in rows:
        words = len(re.sub(r"\]\([^)]*\)", "]", row).replace("|", " ").split())
        if words > 40:
            problems.append(f"README.md, Status: {words} words (at most 40; the detail goes in docs/status.md): {row[:80]}")
        for anchor in re.findall(r"\(docs/status\.md#([\w-]+)\)", row):
            if anchor not in anchors:
                problems.append(f"README.md, Status: docs/status.md has no heading #{anchor}")
    for line in status.splitlines():
        cells = line.strip().strip("|").split("|") if line.startswith("|") else []
        problems += [f"docs/status.md: a cell of {len(c.split())} words (at most 40): {c[:80]}" for c in cells if len(c.split()) > 40]
    for paragraph in re.split(r"\n\s*\n|\n(?=- )", status):
        if not paragraph.startswith("|") and len(paragraph.split()) > 90:
            problems.append(f"docs/status.md: a paragraph of {len(paragraph.split())} words (at most 90): {paragraph[:80]}")
    return problems, len(rows)


def test_the_status_is_short_and_its_detail_in_status_md():
    problems, rows = status_problems(read("README.md"), read("docs/status.md"))
    assert not problems, "\n".join(problems)
    assert rows >= 10


def test_a_long_status_row_fails():
    readme = read("README.md").replace("| done |\n", "| done; " + "and more " * 20 + "|\n", 1)
    readme = readme.replace("docs/status.md#mesh-files", "docs/status.md#mesh-formats")
    problems, _ = status_problems(readme, read("docs/status.md"))
    assert any("at most 40" in problem for problem in problems), problems
    assert any("no heading #mesh-formats" in problem for problem in problems), problems


# The project's history ("until stop 44", "since issue 28", "was 0.76") belongs in the decisions
# log (docs/decisions.md), not in what a user reads.
HISTORY = [r"\bstops? \d+", r"\bissues? \d+", r"(?<!\bis )(?<!\bare )(?<!\bbe )(?<!\bbeen )\bused to\b", r"\bno longer\b",
           r"\(was\b", r", was \d", r"\bwhen written\b", r"\bfirst version\b"]


def history_problems(pages):
    return [f"{page}:{text.count(chr(10), 0, match.start()) + 1}: \"{match.group(0)}\" (say what is true now)"
            for page, text in pages.items() if page != "docs/decisions.md"
            for pattern in HISTORY for match in re.finditer(pattern, text, re.I)]


def test_the_user_docs_tell_no_history():
    problems = history_problems(doc_pages())
    assert not problems, "\n".join(problems)


def test_history_in_a_user_doc_fails():
    pages = {"docs/a.md": "the fixed anchor used to pull it back (until stop 44)\n",
             "docs/b.md": "0.90 of w0 (was 0.76); done (issue 28)\n",
             "docs/decisions.md": "Until stop 49 the port counted the coupling force.\n"}
    problems = history_problems(pages)
    assert len(problems) == 4 and not any("decisions" in problem for problem in problems), problems


def test_the_tests_the_docs_name_exist():
    """`*_test`, `*_bench`, `*_fuzz` and `*.test` (with * as a wildcard) named in the docs are files of test/ or bench/."""
    import fnmatch
    names = set()
    for folder in ("test", "bench"):
        for _, _, files in os.walk(os.path.join(ROOT, folder)):
            names.update(files)
    stems = {os.path.splitext(name)[0] for name in names}
    missing = []
    for page, text in doc_pages().items():
        for name in set(re.findall(r"\b([a-z][a-z0-9_]*_(?:test|bench|fuzz))\b", text)):
            if name not in stems:
                missing.append(f"{page}: {name}")
        for name in set(re.findall(r"\b([a-z][a-z0-9_*]*\.test)\b", text)):
            if not fnmatch.filter(names, name):
                missing.append(f"{page}: {name}")
    assert not missing, "\n".join(sorted(missing))
