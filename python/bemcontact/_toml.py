"""Python values -> TOML text, for problems built from dictionaries (Problem.from_dict).

Only what problem files use: tables, arrays of tables, strings, numbers, booleans and
(nested) arrays of these. Keys that are not bare words are quoted.
"""
import math
import re

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(name):
    name = str(name)
    return name if _BARE_KEY.match(name) else _string(name)


def _string(text):
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\t", "\\t")
    return '"' + escaped + '"'


def _value(value, where):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{where}: {value} is not a finite number")
        return repr(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, dict):
        items = ", ".join(f"{_key(k)} = {_value(v, f'{where}.{k}')}" for k, v in value.items())
        return "{ " + items + " }" if items else "{}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        return _value(value.tolist(), where)
    raise TypeError(f"{where}: cannot write a {type(value).__name__} to a problem file")


def _is_table_array(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, dict) for v in value)


def _emit(lines, path, table):
    # Plain values first, then sub-tables and arrays of tables (TOML's order).
    for name, value in table.items():
        if not isinstance(value, dict) and not _is_table_array(value):
            lines.append(f"{_key(name)} = {_value(value, '.'.join(path + [str(name)]))}")
    for name, value in table.items():
        sub = path + [_key(name)]
        if isinstance(value, dict):
            lines.append("")
            lines.append("[" + ".".join(sub) + "]")
            _emit(lines, sub, value)
        elif _is_table_array(value):
            for item in value:
                lines.append("")
                lines.append("[[" + ".".join(sub) + "]]")
                _emit(lines, sub, item)


def dumps(data):
    """The TOML text of a dictionary (top-level keys become tables)."""
    if not isinstance(data, dict):
        raise TypeError("a problem is a dictionary of tables")
    lines = []
    _emit(lines, [], data)
    return "\n".join(lines).lstrip("\n") + "\n"
