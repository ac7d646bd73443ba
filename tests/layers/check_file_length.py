#!/usr/bin/env python3
"""No source file of src/ or app/ longer than 500 lines: a longer one does several jobs and is
split by job (docs/architecture.md). Exit status 1, naming each file and its length, when one is.

  check_file_length.py [ROOT]       check the project at ROOT (default: this file's project)
  check_file_length.py --self-test  a 501-line file is named, a 500-line one is not
"""
import pathlib
import sys
import tempfile

LIMIT = 500
FOLDERS = ("src", "app")
SUFFIXES = {".h", ".cpp"}


def too_long(root):
    found = []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in SUFFIXES and path.is_file():
                lines = path.read_text(errors="replace").count("\n")
                if lines > LIMIT:
                    found.append((path.relative_to(root), lines))
    return found


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "src").mkdir()
        (root / "app").mkdir()
        (root / "src" / "long.cpp").write_text("x\n" * (LIMIT + 1))
        (root / "app" / "fine.h").write_text("x\n" * LIMIT)
        found = too_long(root)
        if found != [(pathlib.Path("src/long.cpp"), LIMIT + 1)]:
            print(f"self-test: expected only src/long.cpp, got {found}", file=sys.stderr)
            return 1
    print(f"self-test: a file of {LIMIT + 1} lines is named, one of {LIMIT} is not")
    return 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    root = pathlib.Path(argv[0]) if argv else pathlib.Path(__file__).resolve().parents[2]
    found = too_long(root)
    for path, lines in found:
        print(f"{path}: {lines} lines, over {LIMIT}: split it by job", file=sys.stderr)
    longest = max((p.read_text(errors="replace").count("\n"), p.relative_to(root))
                  for f in FOLDERS for p in (root / f).rglob("*") if p.suffix in SUFFIXES)
    print(f"longest: {longest[1]} ({longest[0]} lines); {len(found)} over {LIMIT}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
