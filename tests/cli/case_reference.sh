#!/usr/bin/env bash
# docs/CASE_REFERENCE.md against `sluice schema`: every key of the schema appears in the doc's
# table for its section ("## `[numerics]`", "### `[[walls.planes]]`") with the same type and
# default (markup aside), an interval its text states ("in [0.5, 4]") is the schema's, every
# table of tables has its section, and the doc lists no key the schema lacks. Usage: case_reference.sh SLUICE_EXE SOURCE_DIR
set -euo pipefail
exe=$1
src=$2
"$exe" schema >/dev/null # fails here if the command does
/usr/bin/python3 - "$src/docs/CASE_REFERENCE.md" <("$exe" schema) <<'PY'
import json, re, sys

doc_path, schema_path = sys.argv[1], sys.argv[2]
schema = json.load(open(schema_path))


def plain(s):
    return s.replace("`", "").replace("*", "").replace("\\|", "|").strip()


# section -> key -> (type, default); "neighbours.<operator>" stands for each operator's table.
doc, section, meaning = {}, None, {}
for n, line in enumerate(open(doc_path, encoding="utf-8"), 1):
    m = re.match(r"^#{2,3} `\[\[?([^\]`]+)\]\]?`", line)
    if m:
        section = m.group(1)
        doc.setdefault(section, {})
        continue
    if line.startswith("#"):
        section = None
    elif section and line.startswith("| `"):
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.rstrip("\n"))[1:-1]]
        for key in re.findall(r"`([^`]+)`", cells[0]):
            doc[section][key] = (plain(cells[1]), plain(cells[3]), n)
            meaning[(section, key)] = plain(cells[4]) if len(cells) > 4 else ""


def section_of(table):
    if table.startswith("neighbours.") and table != "neighbours":
        return "neighbours.<operator>"
    return table


errors = []
known = {}
for k in schema:
    table, key = k["table"], k["key"]
    full = f"{table}.{key}" if table else key
    if k["type"] in ("table", "array of tables"):
        if not any(s == section_of(full) or s.startswith(full + ".") for s in doc):
            errors.append(f"{full}: no section for this {k['type']} in the doc")
        continue
    sec = section_of(table)
    known.setdefault(sec, set()).add(key)
    row = doc.get(sec, {}).get(key)
    if row is None:
        errors.append(f"{full}: missing from the doc's [{sec}] table")
        continue
    typ, default, n = row
    if typ != k["type"]:
        errors.append(f"{full} (line {n}): type '{typ}' in the doc, '{k['type']}' in the schema")
    if default != k["default"]:
        errors.append(f"{full} (line {n}): default '{default}' in the doc, "
                      f"'{k['default']}' in the schema")
    # An interval the doc's text gives ("in [0.5, 4]") is the schema's (from its min and max).
    if k["min"] is not None or k["max"] is not None:
        interval = k["range"].replace("each component in ", "").split(";")[0]
        for said in re.findall(r"\bin ([\[(][^\])]*[\])])", meaning[(sec, key)], re.I):
            if said != interval:
                errors.append(f"{full} (line {n}): 'in {said}' in the doc, {interval} in the "
                              f"schema")
for sec, rows in doc.items():
    for key, (_, _, n) in rows.items():
        if key not in known.get(sec, set()):
            errors.append(f"{sec}.{key} (line {n}): in the doc but not in the schema")
for e in errors:
    print("FAIL: docs/CASE_REFERENCE.md:", e)
print(f"case reference: {sum(len(r) for r in doc.values())} documented keys checked against "
      f"{len(schema)} schema entries, {len(errors)} disagreement(s)")
sys.exit(1 if errors else 0)
PY
