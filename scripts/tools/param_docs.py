#!/usr/bin/python3
"""The parameter descriptions that come from the field tables, written or checked.

Usage: param_docs.py --param-tables PROGRAM (--write | --check) ROOT

PROGRAM is the param_tables executable (it prints every parameter set's field table as JSON).
From those tables alone this writes:
  - the comment of every key line of the nodes' YAML files in config/ that names a field
    (`key: value  # TYPE, UNIT, DEFAULT: MEANING`, " (reconfigurable)" for live rows); a line's
    value and the file's other comments are the file's own; a field that none of its set's home
    files names (each row's "home") gets a line there, its default as the value (commented out
    when the default is described in words), at the end of its mapping;
  - each parameter table of the docs between `<!-- param_docs: SET -->` and
    `<!-- /param_docs -->` (one row per field, in table order);
  - the gen.add lines of cfg/*.cfg (the live rows, their range and default).
--write rewrites the stale files (`make docs`); --check changes nothing, names each stale file
with its first differing line and exits 1 (a case of `make test`).
"""
import argparse
import json
import os
import re
import subprocess
import sys

# YAML file -> {key prefix in the file: parameter set}
YAML_FILES = {
    "config/tracking.yaml": {"": "tracking"},
    "config/controller_experiment.yaml": {"": "tracking"},
    "config/controller_sim.yaml": {"": "tracking"},
    "config/paper_law.yaml": {"": "tracking"},
    "config/demo_tracking.yaml": {"": "tracking"},
    "config/driver.yaml": {"": "driver"},
    "config/laser.yaml": {"": "laser"},
    "config/localization.yaml": {"": "localization"},
    "config/teleop.yaml": {"keyboard_teleop/": "keyboard_teleop", "joystick_teleop/": "joystick_teleop"},
}
DOC_FILES = ["docs/ros_api.md", "docs/teleop.md", "docs/robot_file.md"]
CFG_FILES = {"cfg/Tracking.cfg": "tracking", "cfg/Driver.cfg": "driver"}
DOC_BEGIN = re.compile(r"^<!-- param_docs: (\w+)(?: (.*?))? -->$")
DOC_END = "<!-- /param_docs -->"
KEY_LINE = re.compile(r"^(\s*)(# )?([A-Za-z_][A-Za-z0-9_]*):(.*)$")
CFG_TYPES = {"double": "double_t", "int": "int_t", "bool": "bool_t", "string": "str_t"}


def comment_start(rest):
    """Index of the comment's '#' in the text after 'key:' (None: no comment), quotes respected."""
    quote = None
    for i, c in enumerate(rest):
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'":
            quote = c
        elif c == "#" and (i == 0 or rest[i - 1] in " \t"):
            return i
    return None


def yaml_comment(row):
    text = f"{row['type']}, {row['unit']}, {row['default']}: {row['meaning']}"
    return text + (" (reconfigurable)" if row["live"] else "")


def key_paths(lines):
    """(line index, indent, path, rest after 'key:') of every key line, commented-out ones too."""
    found, parents = [], []  # parents: (indent, key) of the enclosing mappings
    for i, line in enumerate(lines):
        m = KEY_LINE.match(line)
        if not m:
            continue
        indent, key, rest = m.group(1), m.group(3), m.group(4)
        while parents and parents[-1][0] >= len(indent):
            parents.pop()
        found.append((i, len(indent), "/".join([p[1] for p in parents] + [key]), rest))
        hash_at = comment_start(rest)
        if not (rest if hash_at is None else rest[:hash_at]).strip():
            parents.append((len(indent), key))
    return found


def add_missing(lines, rows):
    """`lines` with a key line for each row (full path in 'path'), at the end of its mapping."""
    lines = list(lines)
    for row in rows:
        parent, _, key = row["path"].rpartition("/")
        paths = key_paths(lines)
        value = "" if row.get("described") else f" {row['default']}"
        line_of = {p: (i, indent) for i, indent, p, _ in paths}
        if parent and parent not in line_of:
            lines.append(f"{parent}:")
            paths = key_paths(lines)
            line_of = {p: (i, indent) for i, indent, p, _ in paths}
        if parent:
            start, indent = line_of[parent]
            inside = [i for i, _, p, _ in paths if p.startswith(parent + "/")]
            at, pad = (max(inside) if inside else start) + 1, " " * (indent + 2)
        else:
            at, pad = len(lines), ""
            while at > 0 and not lines[at - 1].strip():
                at -= 1
        lines.insert(at, f"{pad}{'' if value else '# '}{key}:{value}")
    return lines


def render_yaml(lines, sets, missing=()):
    """The YAML file's lines with `missing` rows added and the comment of every key line that
    names a field rewritten."""
    out = add_missing(lines, missing)
    for i, _, path, rest in key_paths(out):
        row = None
        for prefix, rows in sets.items():
            if path.startswith(prefix) and path[len(prefix):] in rows:
                row = rows[path[len(prefix):]]
        if row is None:
            continue
        line = out[i]
        hash_at = comment_start(rest)
        head = line[:len(line) - len(rest)] + (rest if hash_at is None else rest[:hash_at]).rstrip()
        column = len(line) - len(rest) + hash_at if hash_at is not None else 29
        out[i] = f"{head.ljust(column - 1)} # {yaml_comment(row)}"
    return out


def cell(text):
    return text.replace("|", "\\|")


def doc_default(row):
    d = row["default"]
    if d == '""':
        return "–"
    if d.startswith('"') and d.endswith('"'):
        return f"`{d[1:-1]}`"
    return d


def render_table(rows, header):
    out = [f"| {header} | Type | Unit | Default | Meaning |", "|---|---|---|---|---|"]
    for r in rows:
        unit = "–" if r["unit"] == "-" else r["unit"]
        meaning = r["meaning"] + (" (reconfigurable)" if r["live"] else "")
        out.append(f"| `{r['key']}` | {r['type']} | {cell(unit)} | {cell(doc_default(r))} | {cell(meaning)} |")
    return out


def render_doc(lines, tables, path):
    out, i = [], 0
    while i < len(lines):
        m = DOC_BEGIN.match(lines[i])
        out.append(lines[i])
        i += 1
        if not m:
            continue
        name, header = m.group(1), m.group(2) or "Parameter"
        if name not in tables:
            sys.exit(f"{path}:{i}: param_docs: no parameter set '{name}' (sets: {', '.join(sorted(tables))})")
        end = next((j for j in range(i, len(lines)) if lines[j] == DOC_END), None)
        if end is None:
            sys.exit(f"{path}:{i}: param_docs: '{DOC_END}' missing after the table of '{name}'")
        out.extend(render_table(tables[name], header))
        out.append(DOC_END)
        i = end + 1
    return out


def render_cfg(lines, rows, path):
    begin = next((i for i, l in enumerate(lines) if l.startswith("from dynamic_reconfigure")), None)
    end = next((i for i, l in enumerate(lines) if l.startswith("exit(gen.generate(")), None)
    if begin is None or end is None:
        sys.exit(f"{path}: param_docs: needs a 'from dynamic_reconfigure' line and an 'exit(gen.generate(' line")
    live = [r for r in rows if r["live"]]
    types = sorted({CFG_TYPES[r["type"]] for r in live})
    body = [f"from dynamic_reconfigure.parameter_generator_catkin import ParameterGenerator, {', '.join(types)}", "",
            "gen = ParameterGenerator()"]
    for r in live:
        text = r["meaning"].replace('"', "'") + ("" if r["unit"] == "-" else f" [{r['unit']}]")
        low, high = r["range"]
        body.append(f'gen.add("{r["key"]}", {CFG_TYPES[r["type"]]}, 0, "{text}", {r["default_value"]!r}, {low!r}, {high!r})')
    return lines[:begin] + body + lines[end:]


def first_difference(old, new):
    for n, (a, b) in enumerate(zip(old, new), start=1):
        if a != b:
            return n, a, b
    n = min(len(old), len(new)) + 1
    return n, old[n - 1] if n <= len(old) else "(end of file)", new[n - 1] if n <= len(new) else "(end of file)"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--param-tables", required=True, help="the param_tables executable")
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", action="store_true", help="rewrite the stale files")
    mode.add_argument("--check", action="store_true", help="exit 1 naming each stale file")
    parser.add_argument("root", help="the package's source folder")
    args = parser.parse_args()
    try:
        run = subprocess.run([args.param_tables], capture_output=True, text=True, check=True)
        tables = json.loads(run.stdout)
    except (OSError, subprocess.CalledProcessError, json.JSONDecodeError) as err:
        sys.exit(f"param_docs: cannot read the field tables from {args.param_tables}: {err}"
                 f"{' (' + err.stderr.strip() + ')' if getattr(err, 'stderr', None) else ''} (build it: make docs)")
    by_key = {name: {r["key"]: r for r in rows} for name, rows in tables.items()}

    # A row is missing when none of its set's home files names it; it gets a line in its own.
    texts = {}
    for rel in YAML_FILES:
        try:
            with open(os.path.join(args.root, rel), encoding="utf-8") as f:
                texts[rel] = f.read().split("\n")
        except OSError as err:
            sys.exit(f"param_docs: cannot read {rel}: {err.strerror}")
    missing = {rel: [] for rel in YAML_FILES}
    for rel, prefixes in YAML_FILES.items():
        for prefix, name in prefixes.items():
            homes = {r["home"] for r in tables[name] if r["home"]}
            named = {p for h in homes for _, _, p, _ in key_paths(texts.get(h, []))}
            for r in tables[name]:
                if r["home"] == rel and prefix + r["key"] not in named:
                    missing[rel].append(dict(r, path=prefix + r["key"]))
    stale = 0
    targets = [(p, "yaml") for p in YAML_FILES] + [(p, "doc") for p in DOC_FILES] + [(p, "cfg") for p in CFG_FILES]
    for rel, kind in targets:
        path = os.path.join(args.root, rel)
        with open(path, encoding="utf-8") as f:
            old = f.read().split("\n")
        if kind == "yaml":
            new = render_yaml(old, {prefix: by_key[name] for prefix, name in YAML_FILES[rel].items()}, missing[rel])
        elif kind == "doc":
            new = render_doc(old, tables, rel)
        else:
            new = render_cfg(old, tables[CFG_FILES[rel]], rel)
        if new == old:
            continue
        stale += 1
        if args.write:
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(new))
            print(f"param_docs: wrote {rel}")
        else:
            n, was, wants = first_difference(old, new)
            print(f"param_docs: {rel} is stale (run `make docs`): line {n} is\n  {was}\nthe field tables make it\n  {wants}")
    if args.check:
        print(f"param_docs: {len(targets) - stale} of {len(targets)} generated files fresh")
    return 1 if args.check and stale else 0


if __name__ == "__main__":
    sys.exit(main())
