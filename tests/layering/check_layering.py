#!/usr/bin/env python3
"""Keep semslam's include graph layered.

The layer table (docs/layers.json) names each layer, its folder ("root") and
its rank, bottom (0) to top. Every C++ source (.h .hpp .cpp .cc .cxx) under a
layer's root belongs to that layer (the deepest root wins if roots nest). The
rules, checked on every quoted include (#include "..."; <...> is ignored):

  1. Down only: a file may include files of its own layer or of a layer of
     strictly lower rank. An include of a higher-ranked layer runs UP.
  2. Siblings: two layers of equal rank may not include each other, unless
     the table's "allowed" list holds the pair (from -> to, one direction).
  3. Forbidden: the table's "forbidden" rules (from-layers may not include
     to-layers) hold on top of the ranks, whatever the ranks say.
  4. Every source under the "every_file_layered_under" folders (src/semslam)
     belongs to a layer, and every include lands on a file of some layer.
  5. No circles: neither among files (the file include graph) nor among
     layers (the graph of layer-to-layer includes).
  6. An include "semslam/..." must name an existing file.

An include "x" resolves, first match wins, to src/x, then x relative to the
including file's folder, then x relative to the including file's layer root
(bench/ceres/A.h may include "Datasets.h" = bench/Datasets.h). Other quoted
includes that resolve to nothing are third-party and are skipped. A layer
root that does not exist is an empty layer.

Each problem is one line "path:line: problem". Exit 0 when clean, 1 when
anything is found, 2 on a bad table or bad arguments.

    python3 tests/layering/check_layering.py [--root REPO] [--table TABLE]
"""

import argparse
import json
import os
import re
import sys
from collections import deque
from dataclasses import dataclass, field

SOURCE_EXTENSIONS = (".h", ".hpp", ".cpp", ".cc", ".cxx")
INCLUDE_RE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
DEFAULT_TABLE = os.path.join("docs", "layers.json")


class TableError(Exception):
    """The layer table is unreadable or inconsistent (exit code 2)."""


@dataclass(frozen=True)
class Layer:
    name: str
    rank: int
    root: str  # relative to the repository, '/'-separated, no trailing '/'
    owns: str


@dataclass
class Table:
    layers: list
    allowed: set = field(default_factory=set)  # {(from, to)}
    forbidden: dict = field(default_factory=dict)  # {(from, to): why}
    layered_under: list = field(default_factory=list)


@dataclass(frozen=True)
class Include:
    source: str  # including file, relative path
    line: int
    text: str  # what is between the quotes
    target: str  # resolved file, relative path, or None


# ---- the table ---------------------------------------------------------------------------------


def load_table(path):
    try:
        with open(path, encoding="utf-8") as stream:
            data = json.load(stream)
    except OSError as error:
        raise TableError(f"cannot read {path}: {error.strerror}")
    except json.JSONDecodeError as error:
        raise TableError(f"{path} is not valid JSON: {error}")
    if not isinstance(data, dict):
        raise TableError("the table must be a JSON object")
    layers = parse_layers(data.get("layers"))
    names = {layer.name: layer for layer in layers}
    return Table(
        layers=layers,
        allowed=parse_allowed(data.get("allowed", []), names),
        forbidden=parse_forbidden(data.get("forbidden", []), names),
        layered_under=[clean_root(p, "every_file_layered_under")
                       for p in string_list(data.get("every_file_layered_under", []),
                                            "every_file_layered_under")],
    )


def parse_layers(entries):
    if not isinstance(entries, list) or not entries:
        raise TableError("'layers' must be a non-empty list")
    layers, roots = [], {}
    for index, entry in enumerate(entries):
        where = f"layers[{index}]"
        if not isinstance(entry, dict):
            raise TableError(f"{where} must be an object")
        name, rank, root, owns = (entry.get(k) for k in ("name", "rank", "root", "owns"))
        if not isinstance(name, str) or not name:
            raise TableError(f"{where}: 'name' must be a non-empty string")
        where = f"{where} ('{name}')"
        if not isinstance(rank, int) or isinstance(rank, bool) or rank < 0:
            raise TableError(f"{where}: 'rank' must be a non-negative integer")
        if not isinstance(owns, str) or not owns.strip():
            raise TableError(f"{where}: 'owns' must be a non-empty string")
        root = clean_root(root, where)
        if any(layer.name == name for layer in layers):
            raise TableError(f"{where}: layer name is used twice")
        if root in roots:
            raise TableError(f"{where}: root '{root}' is also layer '{roots[root]}'")
        roots[root] = name
        layers.append(Layer(name, rank, root, owns))
    return layers


def clean_root(root, where):
    if not isinstance(root, str) or not root.strip():
        raise TableError(f"{where}: a root must be a non-empty string")
    cleaned = os.path.normpath(root).replace(os.sep, "/")
    if os.path.isabs(root) or cleaned == "." or cleaned.startswith(".."):
        raise TableError(f"{where}: root '{root}' must be a folder inside the repository")
    return cleaned


def string_list(value, where):
    """A string or a list of strings, as a list."""
    if isinstance(value, str):
        return [value]
    if isinstance(value, list) and all(isinstance(v, str) for v in value):
        return value
    raise TableError(f"{where} must be a string or a list of strings")


def known_names(value, names, where):
    listed = string_list(value, where)
    for name in listed:
        if name not in names:
            raise TableError(f"{where}: unknown layer '{name}'")
    return listed


def parse_allowed(entries, names):
    if not isinstance(entries, list):
        raise TableError("'allowed' must be a list")
    allowed = set()
    for index, entry in enumerate(entries):
        where = f"allowed[{index}]"
        if not isinstance(entry, dict):
            raise TableError(f"{where} must be an object {{\"from\": ..., \"to\": ...}}")
        for source in known_names(entry.get("from"), names, f"{where}.from"):
            for target in known_names(entry.get("to"), names, f"{where}.to"):
                if source == target or names[source].rank != names[target].rank:
                    raise TableError(f"{where}: '{source}' -> '{target}' is not a pair of "
                                     "sibling layers (same rank, different layer)")
                allowed.add((source, target))
    return allowed


def parse_forbidden(entries, names):
    if not isinstance(entries, list):
        raise TableError("'forbidden' must be a list")
    forbidden = {}
    for index, entry in enumerate(entries):
        where = f"forbidden[{index}]"
        if not isinstance(entry, dict):
            raise TableError(f"{where} must be an object {{\"from\": ..., \"to\": ...}}")
        why = entry.get("why", "")
        if not isinstance(why, str):
            raise TableError(f"{where}.why must be a string")
        for source in known_names(entry.get("from"), names, f"{where}.from"):
            for target in known_names(entry.get("to"), names, f"{where}.to"):
                if source == target:
                    raise TableError(f"{where}: a layer cannot be forbidden to include itself")
                forbidden[(source, target)] = why
    return forbidden


# ---- files and includes ------------------------------------------------------------------------


def walk_sources(repo, folder):
    """Relative paths of the C++ sources under folder (none if it does not exist)."""
    found = []
    for directory, subdirs, files in os.walk(os.path.join(repo, folder)):
        subdirs.sort()
        for name in sorted(files):
            if name.endswith(SOURCE_EXTENSIONS):
                found.append(os.path.relpath(os.path.join(directory, name), repo).replace(os.sep, "/"))
    return found


def layer_of(path, table):
    """The layer whose root holds path (the deepest root if roots nest), or None."""
    holders = [layer for layer in table.layers if path.startswith(layer.root + "/")]
    return max(holders, key=lambda layer: len(layer.root), default=None)


def read_includes(repo, path):
    """(line number, quoted text) of each #include "..." in the file, block comments skipped."""
    includes, in_comment = [], False
    with open(os.path.join(repo, path), encoding="utf-8", errors="replace") as stream:
        for number, line in enumerate(stream, start=1):
            code, in_comment = strip_block_comments(line, in_comment)
            match = INCLUDE_RE.match(code)
            if match:
                includes.append((number, match.group(1)))
    return includes


def strip_block_comments(line, in_comment):
    """The line without /* ... */ parts, and whether a comment is still open at its end."""
    kept = []
    while line:
        if in_comment:
            end = line.find("*/")
            if end < 0:
                return "".join(kept), True
            line, in_comment = line[end + 2:], False
        else:
            start = line.find("/*")
            if start < 0 or "//" in line[:start]:
                kept.append(line)
                break
            kept.append(line[:start] + " ")
            line, in_comment = line[start + 2:], True
    return "".join(kept), in_comment


def resolve(repo, source, text, table):
    """The repository file an include names, or None (see the module docstring)."""
    bases = ["src", os.path.dirname(source)]
    layer = layer_of(source, table)
    if layer is not None:
        bases.append(layer.root)
    for base in bases:
        candidate = os.path.normpath(os.path.join(base, text)).replace(os.sep, "/")
        inside = not (os.path.isabs(candidate) or candidate == ".." or candidate.startswith("../"))
        if inside and os.path.isfile(os.path.join(repo, candidate)):
            return candidate
    return None


def collect(repo, table):
    """The files to check (sorted) and their quoted includes."""
    files = set()
    for layer in table.layers:
        files.update(walk_sources(repo, layer.root))
    for folder in table.layered_under:
        files.update(walk_sources(repo, folder))
    files = sorted(files)
    includes = [Include(path, number, text, resolve(repo, path, text, table))
                for path in files for number, text in read_includes(repo, path)]
    return files, includes


# ---- the rules ---------------------------------------------------------------------------------


def check_unlayered(files, table):
    problems = []
    for path in files:
        if layer_of(path, table) is None:
            problems.append(f"{path}:1: file belongs to no layer (add its folder to the layer table)")
    return problems


def check_include(include, table):
    """The problems of one include: unknown file, unlayered target, up, sibling, forbidden."""
    where = f"{include.source}:{include.line}"
    if include.target is None:
        if include.text.startswith("semslam/"):
            return [f'{where}: include "{include.text}" names no file in the repository']
        return []  # third-party header
    source, target = layer_of(include.source, table), layer_of(include.target, table)
    if source is None:
        return []  # the file itself is reported as unlayered
    if target is None:
        return [f'{where}: include "{include.text}" ({include.target}) lands in no layer']
    if source.name == target.name:
        return []
    problems = []
    edge = f"{source.name} (rank {source.rank}) includes {target.name} (rank {target.rank})"
    if target.rank > source.rank:
        problems.append(f'{where}: upward include "{include.text}": {edge}')
    elif target.rank == source.rank and (source.name, target.name) not in table.allowed:
        problems.append(f'{where}: sibling include "{include.text}": {edge}, '
                        'not in the table\'s "allowed" list')
    if (source.name, target.name) in table.forbidden:
        why = table.forbidden[(source.name, target.name)]
        problems.append(f'{where}: forbidden include "{include.text}": {source.name} may not '
                        f'include {target.name}' + (f" ({why})" if why else ""))
    return problems


def strongly_connected(nodes, edges):
    """Tarjan's strongly connected components (iterative), each a sorted list."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    for start in nodes:
        if start in index:
            continue
        work = [(start, iter(sorted(edges.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            child = next(successors, None)
            if child is None:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    components.append(sorted(component))
            elif child not in index:
                index[child] = low[child] = len(index)
                stack.append(child)
                on_stack.add(child)
                work.append((child, iter(sorted(edges.get(child, ())))))
            elif child in on_stack:
                low[node] = min(low[node], index[child])
    return components


def shortest_circle(start, members, edges):
    """The shortest path start -> ... -> start inside members (start repeated at the end)."""
    parent, queue = {}, deque([start])
    while queue:
        node = queue.popleft()
        for child in sorted(edges.get(node, ())):
            if child == start:
                path = [node]
                while path[-1] != start:
                    path.append(parent[path[-1]])
                return list(reversed(path)) + [start]
            if child in members and child not in parent:
                parent[child] = node
                queue.append(child)
    return [start, start]


def circles(nodes, edges):
    """One shortest circle per knot (strongly connected component with a cycle)."""
    found = []
    for component in strongly_connected(sorted(nodes), edges):
        start = component[0]
        if len(component) > 1 or start in edges.get(start, ()):
            found.append((shortest_circle(start, set(component), edges), component))
    return sorted(found)


def check_file_circles(files, includes):
    edges, at = {}, {}
    for include in includes:
        if include.target is not None:
            edges.setdefault(include.source, set()).add(include.target)
            at.setdefault((include.source, include.target), include.line)
    problems = []
    for circle, knot in circles(files, edges):
        line = at[(circle[0], circle[1])]
        text = f"{circle[0]}:{line}: include circle: " + " -> ".join(circle)
        if len(knot) > len(circle) - 1:
            text += f" (one of the circles through {len(knot)} files: {', '.join(knot)})"
        problems.append(text)
    return problems


def check_layer_circles(includes, table):
    edges, witness = {}, {}
    for include in includes:
        if include.target is None:
            continue
        source, target = layer_of(include.source, table), layer_of(include.target, table)
        if source is None or target is None or source == target:
            continue
        edges.setdefault(source.name, set()).add(target.name)
        witness.setdefault((source.name, target.name), f"{include.source}:{include.line}")
    problems = []
    for circle, knot in circles([layer.name for layer in table.layers], edges):
        steps = list(zip(circle, circle[1:]))
        evidence = "; ".join(f"{a} -> {b} at {witness[(a, b)]}" for a, b in steps)
        text = f"{witness[steps[0]]}: layer circle: " + " -> ".join(circle) + f" ({evidence})"
        if len(knot) > len(circle) - 1:
            text += f" (one of the circles through layers {', '.join(knot)})"
        problems.append(text)
    return problems


def check(repo, table):
    """(files, includes, problems) for the repository at repo."""
    files, includes = collect(repo, table)
    problems = check_unlayered(files, table)
    for include in includes:
        problems.extend(check_include(include, table))
    problems.extend(check_file_circles(files, includes))
    problems.extend(check_layer_circles(includes, table))
    return files, includes, problems


# ---- command line ------------------------------------------------------------------------------


def parse_arguments(argv):
    default_root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser = argparse.ArgumentParser(description="Check that semslam's includes follow the layer table.")
    parser.add_argument("--root", default=default_root,
                        help="repository root (default: the repository holding this script)")
    parser.add_argument("--table", default=None,
                        help=f"layer table (default: ROOT/{DEFAULT_TABLE})")
    return parser.parse_args(argv)


def main(argv=None):
    arguments = parse_arguments(argv)
    repo = os.path.abspath(arguments.root)
    if not os.path.isdir(repo):
        print(f"check_layering: repository root {repo} is not a folder", file=sys.stderr)
        return 2
    table_path = arguments.table or os.path.join(repo, DEFAULT_TABLE)
    try:
        table = load_table(table_path)
    except TableError as error:
        print(f"check_layering: bad layer table {table_path}: {error}", file=sys.stderr)
        return 2
    files, includes, problems = check(repo, table)
    for problem in problems:
        print(problem)
    print(f"layering: {len(files)} files, {len(includes)} includes checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
