#!/usr/bin/env python3
"""Checks the folder map of docs/architecture.md against the code's includes.

Each source folder may include its own headers and those of the folders listed for it below,
nothing else of the project; a folder named internal/ is private to the .cpp files of its
parent; and no two source units (a header with its .cpp) include each other, directly or
around a cycle (internal headers, part of their parent's implementation, aside). Usage: check_layers.py SOURCE_ROOT. Exit 1 with one line per
violation.
"""

import fnmatch
import pathlib
import re
import sys

# folder -> the project folders its sources may include (glob patterns), lowest layer first
LAYERS = {
    "core": [],
    "core/internal": ["core"],
    "controllers": ["core"],
    "sim": ["core", "controllers"],
    "sim/render": ["core", "controllers", "sim"],
    "sim/replay": ["core", "controllers", "sim", "sim/render"],
    "sim/job": ["core", "controllers", "sim", "sim/render", "sim/replay"],
    "planner/collision": ["core"],
    "planner/collision/internal": ["core", "planner/collision"],
    "planner/task_space": ["core"],
    "planner/sampling": ["core", "planner/collision", "planner/task_space"],
    "planner/motion": ["core", "planner/collision", "planner/task_space", "planner/sampling"],
    "planner/search": ["core", "planner/collision", "planner/task_space", "planner/sampling", "planner/motion"],
    "planner/scheduling": ["core", "planner/collision", "planner/task_space", "planner/sampling", "planner/motion",
                           "planner/search"],
    "planner": ["core", "planner/collision", "planner/task_space", "planner/sampling", "planner/motion",
                "planner/search", "planner/scheduling"],
    "tools/plot": ["core", "sim/render"],
    "tools/scenarios": ["core", "planner/sampling"],
    "tools/script": ["core", "planner/collision", "planner/task_space", "planner/sampling"],
    "tools/planning": ["core", "planner"],
    "tools/parallel": [],
    "tools/stress": ["core", "sim", "sim/render", "sim/replay", "tools/planning", "tools/scenarios", "tools/parallel",
                     "tools/plot"],
    "tools/bench": ["core", "sim", "sim/render", "planner/collision", "tools/planning", "tools/scenarios",
                    "tools/parallel", "tools/plot"],
    "tools/cli": ["core", "sim", "sim/*", "planner", "planner/*", "tools/*"],
    "tools/meshgen": ["core"],
    "tools/python": ["core", "sim", "sim/render", "sim/job", "tools/planning", "tools/scenarios", "tools/stress"],
    "tools/export": ["core"],
    "examples/plan_and_simulate": ["core", "sim", "planner"],
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def main(root: pathlib.Path) -> int:
    problems = []
    edges = {}
    files = [p for folder in LAYERS for p in sorted((root / folder).glob("*")) if p.suffix in (".h", ".cpp")]
    if not files:
        print(f"check_layers: no sources under {root}")
        return 1
    for path in files:
        rel = path.relative_to(root)
        folder = rel.parent.as_posix()
        unit = rel.with_suffix("").as_posix()
        for target in INCLUDE.findall(path.read_text(encoding="utf-8")):
            target_folder = pathlib.PurePosixPath(target).parent.as_posix()
            if target_folder not in LAYERS:
                if (root / target).exists():
                    problems.append(f"{rel}: includes {target}, from a folder the layer map does not list")
                continue
            private = target_folder.endswith("/internal")
            if private:
                allowed = folder == target_folder or (rel.suffix == ".cpp" and target_folder == folder + "/internal")
            else:
                allowed = target_folder == folder or any(fnmatch.fnmatch(target_folder, p) for p in LAYERS[folder])
            if not allowed:
                problems.append(f"{rel}: includes {target}: {folder}/ may not include {target_folder}/")
            target_unit = pathlib.PurePosixPath(target).with_suffix("").as_posix()
            if target_unit != unit and not private:
                edges.setdefault(unit, set()).add(target_unit)
    problems += [f"include cycle: {' -> '.join(cycle)}" for cycle in cycles(edges)]
    for line in problems:
        print(line)
    print(f"check_layers: {len(files)} files, {len(problems)} problems")
    return 1 if problems else 0


def cycles(edges):
    """One cycle per strongly connected component of more than one unit (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component) + [sorted(component)[0]])

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
