#!/usr/bin/env python3
"""Convert glass catalogues of the refractiveindex.info database into data/glass/<maker>.json.

The database (github.com/polyanskiy/refractiveindex.info-database) is public domain (CC0 1.0).
Its database/data/specs/<maker>/<group>/<NAME>.yml files hold each glass's dispersion formula
(wavelengths in air, micrometres; indices relative to air, as the makers publish them), the
formula's validity range, the extinction coefficient k against wavelength and the catalogue's
n_d and V_d. This is a maintainer's tool: the build and the tests read only its output.

    tools/convert_glass_catalogues.py DATABASE_DIR [-o data/glass] [--revision COMMIT]

DATABASE_DIR is a checkout of the database (the folder holding database/). Each output file
holds one glass per line, so a new database version shows as a readable diff.
"""

import argparse
import html
import json
import math
import pathlib
import re
import subprocess
import sys

import yaml

MAKERS = {  # folder in the database -> name used in lenslab (MAKER:NAME)
    "schott": "SCHOTT",
    "ohara": "OHARA",
    "cdgm": "CDGM",
    "hoya": "HOYA",
    "hikari": "HIKARI",
    "sumita": "SUMITA",
}

# Fraunhofer lines (air wavelengths, micrometres) for the converter's own consistency check.
LINE_D, LINE_F, LINE_C = 0.5875618, 0.4861327, 0.6562725


def numbers(text, where):
    try:
        return [float(x) for x in str(text).split()]
    except ValueError as e:
        sys.exit(f"{where}: {e}")


def table(text, where):
    values = numbers(text, where)
    if len(values) % 2:
        sys.exit(f"{where}: a table needs wavelength/value pairs, got {len(values)} numbers")
    return [[values[i], values[i + 1]] for i in range(0, len(values), 2)]


def first_reference(references):
    """The first link's text of the REFERENCES field (HTML or Markdown), as plain text."""
    text = str(references or "").strip()
    m = re.search(r"<a [^>]*>(.*?)</a>", text) or re.search(r"\[([^\]]+)\]\(", text)
    text = m.group(1) if m else text.splitlines()[0] if text else "unknown"
    return html.unescape(re.sub(r"<[^>]+>", "", text)).strip()


def index_at(glass, um):
    """n at an air wavelength in um, for the formulas this converter emits (1, 2, 3)."""
    c = glass.get("coefficients", [])
    f = glass["formula"]
    if f == 1:
        return math.sqrt(1 + c[0] + sum(c[i] * um**2 / (um**2 - c[i + 1] ** 2) for i in range(1, len(c), 2)))
    if f == 2:
        return math.sqrt(1 + c[0] + sum(c[i] * um**2 / (um**2 - c[i + 1]) for i in range(1, len(c), 2)))
    if f == 3:
        return math.sqrt(c[0] + sum(c[i] * um ** c[i + 1] for i in range(1, len(c), 2)))
    return None


def convert_glass(path, group, references):
    where = str(path)
    doc = yaml.safe_load(path.read_text(encoding="utf-8"))
    glass = {"name": path.stem, "group": group}
    for entry in doc.get("DATA", []):
        kind = entry["type"]
        if kind.startswith("formula "):
            glass["formula"] = int(kind.split()[1])
            glass["coefficients"] = numbers(entry["coefficients"], where)
            glass["range_um"] = numbers(entry["wavelength_range"], where)
        elif kind == "tabulated n":
            glass["formula"] = "tabulated"
            glass["n"] = table(entry["data"], where)
        elif kind == "tabulated k":
            glass["k"] = table(entry["data"], where)
        else:
            return None, f"data type '{kind}' is not converted"
    if "formula" not in glass:
        return None, "no refractive index data"
    if glass["formula"] == "tabulated" and len(glass["n"]) < 2:
        return None, "an index table of fewer than two wavelengths"
    props = doc.get("PROPERTIES") or {}
    if "nd" in props and "Vd" in props:
        glass["n_d"] = float(props["nd"])
        glass["V_d"] = float(props["Vd"])
    for key, out in (("glass_code", "code"), ("glass_status", "status")):
        if key in props:
            glass[out] = str(props[key])
    ref = first_reference(doc.get("REFERENCES"))
    if ref not in references:
        references.append(ref)
    glass["ref"] = references.index(ref)
    # Keep the key order stable: identity, model, catalogue values, k last (the long part).
    order = ["name", "group", "formula", "coefficients", "range_um", "n", "n_d", "V_d", "code",
             "status", "ref", "k"]
    return {k: glass[k] for k in order if k in glass}, None


def database_commit(root):
    try:
        return subprocess.run(["git", "-C", str(root), "rev-parse", "--short=12", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_catalogue(out_path, maker, folder, commit, references, glasses):
    header = {
        "maker": maker,
        "source": f"refractiveindex.info database, database/data/specs/{folder} (commit {commit})",
        "license": "CC0 1.0 (public domain), M. N. Polyanskiy, refractiveindex.info",
        "conventions": "wavelengths in air, micrometres; indices relative to air",
        "references": references,
    }
    lines = ["{"]
    for key, value in header.items():
        lines.append(f"  {json.dumps(key)}: {json.dumps(value, ensure_ascii=False)},")
    lines.append('  "glasses": [')
    body = [json.dumps(g, separators=(",", ":"), ensure_ascii=False) for g in glasses]
    lines.append(",\n".join("    " + b for b in body))
    lines.append("  ]")
    lines.append("}")
    out_path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("database", type=pathlib.Path, help="checkout of refractiveindex.info-database")
    parser.add_argument("-o", "--output", type=pathlib.Path, default=pathlib.Path("data/glass"))
    parser.add_argument("--revision", help="the database commit, when DATABASE is not a git "
                        "checkout (e.g. a `git archive` export)")
    args = parser.parse_args()
    specs = args.database / "database" / "data" / "specs"
    if not specs.is_dir():
        sys.exit(f"{specs}: not found (pass the folder that holds database/)")
    commit = args.revision or database_commit(args.database)
    args.output.mkdir(parents=True, exist_ok=True)
    total = 0
    for folder, maker in MAKERS.items():
        references, glasses = [], []
        for path in sorted((specs / folder).glob("*/*.yml")):
            glass, why = convert_glass(path, path.parent.name, references)
            if glass is None:
                print(f"{maker}: skipped {path.parent.name}/{path.stem}: {why}", file=sys.stderr)
                continue
            glasses.append(glass)
            if "n_d" in glass and index_at(glass, LINE_D):
                n_d = index_at(glass, LINE_D)
                v_d = (n_d - 1) / (index_at(glass, LINE_F) - index_at(glass, LINE_C))
                if abs(n_d - glass["n_d"]) > 5e-6 or abs(v_d - glass["V_d"]) > 0.01:
                    print(f"{maker}: {glass['name']}: the formula gives n_d {n_d:.6f}, V_d "
                          f"{v_d:.3f}; the catalogue says {glass['n_d']}, {glass['V_d']}",
                          file=sys.stderr)
        glasses.sort(key=lambda g: g["name"].upper())
        write_catalogue(args.output / f"{folder}.json", maker, folder, commit, references, glasses)
        print(f"{maker}: {len(glasses)} glasses -> {args.output / (folder + '.json')}")
        total += len(glasses)
    print(f"{total} glasses")


if __name__ == "__main__":
    main()
