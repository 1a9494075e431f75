"""A scene given as a Python dict, written as the TOML text of a scene file.

The text then goes through the command line's own reader (stc::parseScene), so a dict gets every
check a file gets, with the same messages. Python values map to TOML as a file would write them:

    bool -> boolean, int -> integer, float -> float (inf, nan included), str -> string,
    list / tuple / 1-D NumPy array -> array, dict -> table; a list of dicts -> array of tables.

A value TOML cannot hold (None, an object) is refused with InputError (a ValueError) naming the key.
Strings are written with every non-ASCII character escaped, so the text itself is ASCII.
"""

import math
import numbers
import re
from collections.abc import Mapping

import numpy

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}


class SceneValueError(ValueError):
    """A dict value with no TOML counterpart (raised as stcontact.InputError by the package)."""


def _string(text):
    out = []
    for char in text:
        code = ord(char)
        if char in _ESCAPES:
            out.append(_ESCAPES[char])
        elif code < 0x20 or code == 0x7F:
            out.append("\\u%04X" % code)
        elif code > 0x7F:
            out.append("\\u%04X" % code if code <= 0xFFFF else "\\U%08X" % code)
        else:
            out.append(char)
    return '"' + "".join(out) + '"'


def _key(key, path):
    if not isinstance(key, str):
        raise SceneValueError("key %r in '%s' must be a string" % (key, path or "the scene"))
    return key if _BARE_KEY.match(key) else _string(key)


def _path(parent, key):
    return "%s.%s" % (parent, key) if parent else str(key)


def _float(value):
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return repr(float(value))


def toml_value(value, path=""):
    """The TOML text of one value (inline: arrays and tables on one line)."""
    if isinstance(value, (bool, numpy.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return _float(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, Mapping):
        items = ("%s = %s" % (_key(k, path), toml_value(v, _path(path, k))) for k, v in value.items())
        return "{" + ", ".join(items) + "}"
    if isinstance(value, numpy.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v, "%s[%d]" % (path, i)) for i, v in enumerate(value)) + "]"
    raise SceneValueError("key '%s' = %r has no TOML value (give a bool, number, string, list or dict)"
                          % (path, value))


def _is_table_array(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, Mapping) for v in value)


def _table(lines, table, path, header):
    """The key = value lines of `table`, then its sub-tables, then its arrays of tables. `path` names
    keys in messages (array entries indexed), `header` is the table's header (keys quoted as needed)."""
    for key, value in table.items():
        if not isinstance(value, Mapping) and not _is_table_array(value):
            lines.append("%s = %s" % (_key(key, path), toml_value(value, _path(path, key))))
    for key, value in table.items():
        if isinstance(value, Mapping):
            sub_header = _path(header, _key(key, path))
            lines.extend(["", "[%s]" % sub_header])
            _table(lines, value, _path(path, key), sub_header)
    for key, value in table.items():
        if _is_table_array(value):
            sub_header = _path(header, _key(key, path))
            for index, entry in enumerate(value):
                lines.extend(["", "[[%s]]" % sub_header])
                _table(lines, entry, "%s[%d]" % (_path(path, key), index), sub_header)


def scene_toml(scene):
    """The TOML text of a scene dict (the keys of docs/scene_format.md)."""
    if not isinstance(scene, Mapping):
        raise SceneValueError("a scene must be a dict of the scene file's keys, not %s" % type(scene).__name__)
    lines = []
    _table(lines, scene, "", "")
    return "\n".join(lines) + "\n"


def override_text(key, value):
    """One --set text from a key and a Python value: ("contact.friction", 0.3) -> contact.friction=0.3."""
    return "%s=%s" % (key, toml_value(value, key))
