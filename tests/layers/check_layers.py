#!/usr/bin/env python3
"""The include graph of src/ against the layer order of cmake/layers.cmake.

Every folder of src/ is a layer; a file may include headers of its own layer and of the layers
listed before it, never of one listed after it. The build already fails on such an include (each
layer's library sees only the include roots below it); this names every offending line at once,
with the layer graph it read, so a reader sees the whole picture rather than the first compile
error. Exit status 1 when an edge points up or a folder is in no layer.

  check_layers.py [ROOT]      check the project at ROOT (default: this file's project)
  check_layers.py --self-test build a small tree with one upward include and check it is named
"""
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^[ \t]*#[ \t]*include\s+"([^"/]+)/[^"]+"', re.MULTILINE)
SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".in"}


def declared_layers(root):
    text = re.sub(r"#[^\n]*", "", (root / "cmake" / "layers.cmake").read_text())
    match = re.search(r"set\(LENSLAB_LAYERS(.*?)\)", text, re.DOTALL)
    if not match:
        raise SystemExit("cmake/layers.cmake: no set(LENSLAB_LAYERS ...)")
    return match.group(1).split()


def include_edges(root, layers):
    """(file, line, from_layer, to_layer) for every include of a layer's header."""
    src = root / "src"
    for path in sorted(src.rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
            continue
        from_layer = path.relative_to(src).parts[0]
        text = path.read_text(errors="replace")
        for match in INCLUDE.finditer(text):
            to_layer = match.group(1)
            if to_layer in layers or (src / to_layer).is_dir():
                line = text.count("\n", 0, match.start()) + 1
                yield path.relative_to(root), line, from_layer, to_layer


def check(root):
    layers = declared_layers(root)
    rank = {name: i for i, name in enumerate(layers)}
    problems = []
    for folder in sorted(p.name for p in (root / "src").iterdir() if p.is_dir()):
        if folder not in rank:
            problems.append(f"src/{folder}: a folder in no layer (add it to cmake/layers.cmake)")
    graph = {}
    for path, line, source, target in include_edges(root, layers):
        if source not in rank or target not in rank:
            continue  # the folder itself is reported above
        if source != target:
            graph.setdefault(source, set()).add(target)
        if rank[target] > rank[source]:
            problems.append(f"{path}:{line}: includes {target}/, a layer above {source} "
                            f"(order: {' < '.join(layers)})")
    return layers, graph, problems


def report(root):
    layers, graph, problems = check(root)
    for name in layers:
        below = sorted(graph.get(name, ()), key=layers.index)
        print(f"{name:10} includes {', '.join(below) if below else '(nothing)'}")
    edges = sum(len(t) for t in graph.values())
    print(f"{len(layers)} layers, {edges} layer-to-layer include edges, "
          f"{len(problems)} against the order")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "cmake").mkdir()
        (root / "cmake" / "layers.cmake").write_text("set(LENSLAB_LAYERS\n low # first\n high)\n")
        for layer in ("low", "high", "stray"):
            (root / "src" / layer).mkdir(parents=True)
        (root / "src" / "high" / "b.h").write_text('#include "low/a.h"\n')
        (root / "src" / "low" / "a.h").write_text('#pragma once\n\n#include "high/b.h"\n')
        _, graph, problems = check(root)
        expected = [
            "src/stray: a folder in no layer (add it to cmake/layers.cmake)",
            "src/low/a.h:3: includes high/, a layer above low (order: low < high)",
        ]
        if problems != expected or graph != {"low": {"high"}, "high": {"low"}}:
            print(f"self-test: expected {expected}\n got {problems}, graph {graph}",
                  file=sys.stderr)
            return 1
    print("self-test: the upward include and the stray folder are both named")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    here = pathlib.Path(__file__).resolve().parents[2]
    sys.exit(report(pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here))
