"""The layer tables (docs/DESIGN.md, Layers; README.md, Layout) against CMake's link graph.

CMake's graph: every library and program built from one folder src/LAYER/ (god_finger_support,
god_finger_device_registry: devices, the tools: tools, ...), with the god_finger targets its
target_link_libraries names (variables expanded). A table row names one or more layers and the
layers it depends on; what else its "depends on" cell names (Eigen, Bullet) is not CMake's
targets and is not compared. The two must agree:
  - every edge a table gives is a link CMake makes (directly);
  - every link CMake makes is reached in the table, directly or through the rows below
    (contact links support itself; its row says geometry, whose row says support);
  - every layer CMake builds has a row, and every row's layer is built;
  - each row depends only on rows above it.
Needs nothing built: it reads CMakeLists.txt and the pages.
"""
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# --- CMake ---------------------------------------------------------------------------------------

def cmake_commands(text):
    """(name, [arguments]) of every command, comments stripped, foreach loops unrolled."""
    text = re.sub(r"#[^\n]*", "", text)
    commands, position = [], 0
    for match in re.finditer(r"\b([A-Za-z_]\w*)\s*\(", text):
        if match.start() < position:
            continue  # a word inside the previous command's arguments
        depth, position = 1, match.end()
        while depth and position < len(text):
            depth += {"(": 1, ")": -1}.get(text[position], 0)
            position += 1
        body = text[match.end():position - 1]
        commands.append((match.group(1).lower(), re.findall(r'"[^"]*"|[^\s"]+', body)))
    return unroll(commands)


def unroll(commands):
    out, index = [], 0
    while index < len(commands):
        name, args = commands[index]
        if name != "foreach":
            out.append((name, args))
            index += 1
            continue
        depth, end = 1, index + 1
        while depth:
            depth += {"foreach": 1, "endforeach": -1}.get(commands[end][0], 0)
            end += 1
        body = unroll(commands[index + 1:end - 1])
        for item in args[1:]:
            out.extend((n, [a.replace("${" + args[0] + "}", item) for a in body_args]) for n, body_args in body)
        index = end
    return out


def cmake_link_graph(text):
    """{layer: {layers it links}} and {layer: [the targets built from it]}."""
    variables = {}

    def expand(words):
        out = []
        for word in words:
            whole = re.fullmatch(r"\$\{(\w+)\}", word)
            out.extend(variables.get(whole.group(1), []) if whole else [word])
        return out

    layer_of, links = {}, {}
    for name, args in cmake_commands(text):
        if not args:
            continue
        if name == "set":
            variables[args[0]] = expand(args[1:])
        elif name == "list" and args[0] == "APPEND":
            variables.setdefault(args[1], []).extend(expand(args[2:]))
        elif name == "file" and args[0] in ("GLOB", "GLOB_RECURSE"):
            variables[args[1]] = [a for a in args[2:] if a != "CONFIGURE_DEPENDS"]
        elif name in ("add_library", "add_executable"):
            folders = {m.group(1) for m in (re.match(r"src/(\w+)/", source) for source in expand(args[1:])) if m}
            sources = [source for source in expand(args[1:]) if "/" in source]
            # A target of one layer: every source under src/LAYER/ (the float32 physics, built from
            # three layers' sources for a benchmark, and the tests' programs are none).
            if len(folders) == 1 and all(source.startswith("src/") for source in sources):
                layer_of[args[0]] = folders.pop()
        elif name == "target_link_libraries":
            links.setdefault(args[0], []).extend(expand(args[1:]))
    graph = {layer: set() for layer in layer_of.values()}
    targets = {}
    for target, layer in layer_of.items():
        targets.setdefault(layer, []).append(target)
        for item in links.get(target, []):
            if item in layer_of and layer_of[item] != layer:
                graph[layer].add(layer_of[item])
    return graph, targets


# --- the pages' tables ---------------------------------------------------------------------------

def layer_table(page, heading, text=None):
    """[(layers the row names, the cell's words)] of the first table under `## heading`."""
    text = text if text is not None else open(os.path.join(ROOT, page)).read()
    section = re.search(rf"^## {re.escape(heading)}\b.*?(?=^## |\Z)", text, re.S | re.M)
    assert section, f"{page} has no section '## {heading}'"
    rows = []
    for line in section.group(0).splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) < 2 or set(cells[0]) <= set("-") or cells[0] in ("layer", "library"):
            continue
        names = [name.strip(" `") for name in cells[0].split(",")]
        # The first word of each item of "depends on": "haptics (the vendor glue: ...)", "Bullet (float64)".
        words = [re.sub(r"[`()]", "", item.strip()).split(" ")[0] for item in re.split(r"[,;]", cells[1]) if item.strip()]
        rows.append((names, words))
    assert rows, f"{page}, {heading}: no table"
    return rows


def compare(page, heading, cmake=None, page_text=None):
    """The differences between the page's table and CMake's graph, one line each (none: they agree).
    cmake, page_text: edited copies of CMakeLists.txt and the page."""
    graph, targets = cmake_link_graph(cmake if cmake is not None else open(os.path.join(ROOT, "CMakeLists.txt")).read())
    rows = layer_table(page, heading, page_text)
    row_of = {name: index for index, (names, _) in enumerate(rows) for name in names}
    problems = []
    for layer in sorted(graph):
        if layer not in row_of:
            problems.append(f"CMake builds layer '{layer}' ({', '.join(sorted(targets[layer]))}); {page} has no row for it")
    for name in sorted(row_of):
        if name not in graph:
            problems.append(f"{page} has a row for '{name}'; CMake builds no target from src/{name}/")
    # The table's edges, between rows (a row naming ros and nodes holds the link between them).
    table = {index: {row_of[word] for word in words if word in row_of} - {index} for index, (_, words) in enumerate(rows)}

    # Reached through the table's edges that CMake makes (an edge CMake lacks is named below, and
    # reaches nothing).
    linked = {index: {below for below in table[index]
                      if any(name in graph and set(rows[below][0]) & graph[name] for name in rows[index][0])}
              for index in table}

    def reached(start):
        seen, todo = set(), [start]
        while todo:
            for below in linked[todo.pop()]:
                if below not in seen:
                    seen.add(below)
                    todo.append(below)
        return seen

    for index, (names, words) in enumerate(rows):
        for word in words:
            if word in row_of and row_of[word] != index and not any(word in graph.get(name, ()) for name in names):
                problems.append(f"{page}: {' / '.join(names)} -> {word}, but CMake links no {word} target into "
                                f"{' / '.join(names)} (target_link_libraries of {', '.join(t for n in names for t in targets.get(n, []))})")
    for index, below in sorted((i, b) for i, deps in table.items() for b in deps):
        if below > index:
            problems.append(f"{page}: {' / '.join(rows[index][0])} depends on {' / '.join(rows[below][0])}, a row below it "
                            "(each layer depends only on the rows above it)")
    for layer in sorted(graph):
        if layer not in row_of:
            continue
        for below in sorted(graph[layer]):
            if below in row_of and row_of[below] != row_of[layer] and row_of[below] not in reached(row_of[layer]):
                problems.append(f"CMake: {layer} -> {below} (target_link_libraries of {', '.join(sorted(targets[layer]))}); "
                                f"{page}'s table does not reach {below} from {layer}")
    return problems


TABLES = [("docs/DESIGN.md", "Layers"), ("README.md", "Layout")]


@pytest.mark.parametrize("page,heading", TABLES)
def test_the_layer_table_is_cmakes_link_graph(page, heading):
    problems = compare(page, heading)
    assert not problems, "\n".join(problems)


def test_cmakes_graph_is_read():
    """The parse finds the layers and the links the tables are checked against."""
    graph, targets = cmake_link_graph(open(os.path.join(ROOT, "CMakeLists.txt")).read())
    for layer in ("support", "geometry", "contact", "haptics", "soft", "mesh_io", "scene", "physics", "devices",
                  "runtime", "scenarios", "ros", "nodes", "tools", "python"):
        assert layer in graph, layer
    assert "god_finger_device_registry" in targets["devices"]
    assert "god_finger_experiment" in targets["tools"]
    assert {"runtime", "physics"} <= graph["scenarios"]
    assert "ros" in graph["nodes"]


@pytest.mark.parametrize("page,heading", TABLES)
def test_an_edge_missing_from_either_side_is_named(page, heading):
    """A link dropped from a copy of CMakeLists.txt, one added to it, and an edge dropped from a copy
    of the table: each fails, naming the edge."""
    cmake = open(os.path.join(ROOT, "CMakeLists.txt")).read()
    without_soft = re.sub(r"(target_link_libraries\(god_finger_scene god_finger_mesh_io) god_finger_soft", r"\1", cmake)
    assert without_soft != cmake
    problems = compare(page, heading, without_soft)
    assert any("scene -> soft" in problem and "CMake links no soft" in problem for problem in problems), problems

    without_devices = re.sub(r"(target_link_libraries\(god_finger_runtime god_finger_physics) god_finger_devices",
                             r"\1", cmake)
    assert without_devices != cmake
    problems = compare(page, heading, without_devices)
    assert any("runtime -> devices" in problem for problem in problems), problems

    with_runtime_scenarios = cmake.replace("target_link_libraries(god_finger_runtime god_finger_physics",
                                           "target_link_libraries(god_finger_runtime god_finger_scenarios god_finger_physics")
    problems = compare(page, heading, with_runtime_scenarios)
    assert any("CMake: runtime -> scenarios" in problem for problem in problems), problems

    page_text = open(os.path.join(ROOT, page)).read()
    row = re.search(r"^\| `scene` \|[^|]*\|", page_text, re.M).group(0)
    edited = page_text.replace(row, row.replace(" soft,", ""))
    assert edited != page_text
    problems = compare(page, heading, page_text=edited)
    assert any(problem.startswith("CMake: scene -> soft") for problem in problems), problems

    # A row moved above a layer it depends on.
    lines = page_text.split("\n")
    scene = next(i for i, line in enumerate(lines) if line.startswith("| `scene` |"))
    soft = next(i for i, line in enumerate(lines) if line.startswith("| `soft` |"))
    lines[scene], lines[soft] = lines[soft], lines[scene]
    problems = compare(page, heading, page_text="\n".join(lines))
    assert any("scene depends on soft, a row below it" in problem for problem in problems), problems
