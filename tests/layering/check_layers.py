#!/usr/bin/python3
"""The layers of docs/architecture.md against the code and the build.

    tests/layering/check_layers.py [ROOT]

Reads the table under "## Layers" in ROOT/docs/architecture.md (folder | job | may include),
then:
  - every #include "X/..." in ROOT/src names a folder its file's folder may include (or its own);
    each one that does not is reported as FILE:LINE with what it includes and what is allowed;
  - every folder of src/ with sources is in the table, and every folder in the table exists;
  - the candela_layer(...) calls of ROOT/CMakeLists.txt link exactly the table's folders (the
    build then refuses what this check refuses: a library sees only the headers of what it links).
Exits 1 naming each problem, 0 when there is none.
"""
import os
import re
import sys

# A folder inside another that is a layer of its own, by the name the table gives it.
INNER_LAYERS = {"film/output": "io"}


def fail_usage(message):
    sys.exit("check_layers.py: " + message)


def read_table(path):
    """{layer: set of layers it may include} from the Layers table, in the table's order."""
    try:
        lines = open(path, encoding="utf-8").read().splitlines()
    except OSError as e:
        fail_usage("%s: %s" % (path, e.strerror))
    try:
        start = lines.index("## Layers")
    except ValueError:
        fail_usage("%s: no '## Layers' section" % path)
    table = {}
    for number, line in enumerate(lines[start + 1:], start + 2):
        if line.startswith("## "):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")] if line.startswith("|") else []
        if len(cells) != 3 or cells[0] in ("folder", "") or set(cells[0]) <= set("-: "):
            continue
        folder = cells[0].strip("`")
        uses = cells[2].replace("`", "")
        allowed = set() if uses in ("-", "—", "") else {u.strip() for u in uses.split(",")}
        if folder in table:
            fail_usage("%s:%d: %s is in the table twice" % (path, number, folder))
        table[folder] = allowed
    if not table:
        fail_usage("%s: the Layers section has no table" % path)
    return table


def layer_of(relative):
    """The layer of a path below src/ ("lights/light.h" -> lights, "film/output/x.h" -> io)."""
    for inner, name in INNER_LAYERS.items():
        if relative.startswith(inner + "/"):
            return name
    return relative.split("/", 1)[0]


def check_includes(root, table):
    problems = []
    src = os.path.join(root, "src")
    include = re.compile(r'\s*#\s*include\s+"([^"]+)"')
    seen = set()
    for directory, _, files in sorted(os.walk(src)):
        for f in sorted(files):
            if not f.endswith((".h", ".cpp")):
                continue
            path = os.path.join(directory, f)
            relative = os.path.relpath(path, src)
            here = layer_of(relative)
            seen.add(here)
            allowed = table.get(here)
            shown = os.path.relpath(path, root)
            if allowed is None:
                problems.append("%s: its folder %s is not in the Layers table" % (shown, here))
                continue
            with open(path, encoding="utf-8", errors="replace") as text:
                for number, line in enumerate(text, 1):
                    m = include.match(line)
                    if not m or "/" not in m.group(1):
                        continue
                    target = layer_of(m.group(1))
                    if target not in table:
                        continue  # not one of ours (a library's header)
                    if target != here and target not in allowed and "all" not in allowed:
                        problems.append("%s:%d: includes %s, but %s may include only %s" %
                                        (shown, number, m.group(1), here,
                                         ", ".join(sorted(allowed)) or "itself"))
    for folder in table:
        if folder not in seen:
            problems.append("docs/architecture.md: layer %s has no files under src/" % folder)
    return problems


def check_build(root, table):
    """The candela_layer calls' USES lists are the table's (less the layer itself)."""
    text = open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8").read()
    text = re.sub(r"#[^\n]*", "", text)
    problems = []
    found = {}
    for m in re.finditer(r"candela_layer\(\s*(\w+)([^)]*)\)", text):
        name, args = m.group(1), m.group(2).split()
        uses, keyword = set(), None
        for a in args:
            if a in ("FOLDER", "USES", "LIBS", "PRIVATE_LIBS"):
                keyword = a
            elif keyword == "USES":
                uses.add(a)
        found[name] = uses
    for name, uses in found.items():
        if name not in table:
            problems.append("CMakeLists.txt: layer %s is not in docs/architecture.md" % name)
        elif uses != table[name] - {name}:
            problems.append("CMakeLists.txt: candela_%s links %s; docs/architecture.md says %s" %
                            (name, ", ".join(sorted(uses)) or "nothing",
                             ", ".join(sorted(table[name] - {name})) or "nothing"))
    for name, allowed in table.items():
        if name not in found and "all" not in allowed:
            problems.append("CMakeLists.txt: no candela_layer(%s ...) for the table's %s" %
                            (name, name))
    return problems


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), "..", ".."))
    table = read_table(os.path.join(root, "docs", "architecture.md"))
    problems = check_includes(root, table) + check_build(root, table)
    for p in problems:
        print(p)
    if problems:
        print("%d layering problem(s) (docs/architecture.md, Layers)" % len(problems))
        return 1
    print("layers: %d folders, every include and link as docs/architecture.md says" % len(table))
    return 0


if __name__ == "__main__":
    sys.exit(main())
