"""The schema model: every *.schema.toml of the project loaded into one set of named
constants, enums and values, with their fields' types resolved and each value's layout id.

A schema file (TOML) holds:
  [schema]     doc; cpp (the C++ header written next to the file; omit for GDScript-only
               values); gdscript (the folder, from the project root, of the GDScript classes;
               omit for C++-only values); gd_constants (the GDScript class that carries the
               file's constants and enums); cpp_includes (extra headers the C++ needs);
               gd_extends (a file of network messages: their GDScript classes' base, which
               extends HapticsValue and declares label(), channel(), transfer_mode(),
               from_server() and to_server(); other values extend HapticsValue)
  [constants.NAME]  value, doc
  [enums.Name]      values (lowercase names in order), doc, gd (name in gd_constants)
  [values.Name]     gd (the GDScript class), doc, realtime (C++: trivially copyable, fixed
                    capacity), fields.<name> = { type, doc, unit, min, max, default,
                    max_count, max_length (a number or a constant's name), nonzero,
                    finite }; a network message (GDScript
                    only) adds channel (a number or a constant's name), transfer
                    ("reliable", "unreliable" or "unreliable_ordered"), label (words for
                    people), sender and receiver ("any", the default, or "server"), and may
                    have no fields
A vector's max is its longest length; its min (GDScript only) its shortest.
The wire format and the types are described in docs/values.md (written from here too).
"""

import os
import re
import tomllib
from dataclasses import dataclass, field, replace

# Scalar types: C++ type, GDScript type, GDScript zero, wire kind.
SCALARS = {
    "bool": ("bool", "bool", "false"),
    "int": ("int32_t", "int", "0"),
    "int64": ("int64_t", "int", "0"),
    "uint8": ("uint8_t", "int", "0"),
    "uint16": ("uint16_t", "int", "0"),
    "uint32": ("uint32_t", "int", "0"),
    "uint64": ("uint64_t", "int", "0"),
    "float": ("double", "float", "0.0"),
    "float32": ("float", "float", "0.0"),
    "vec2": ("Vec2", "Vector2", "Vector2.ZERO"),
    "vec3": ("Vec3", "Vector3", "Vector3.ZERO"),
    "vec2f": ("Vec2", "Vector2", "Vector2.ZERO"),
    "vec3f": ("Vec3", "Vector3", "Vector3.ZERO"),
    # A 2D game vector (x right, y down): Vector2 in GDScript, a device-space Vec3 (x right,
    # y up, z 0) in C++; the C++ codec flips y (core/base/coordinates.h).
    "game_vec2": ("Vec3", "Vector2", "Vector2.ZERO"),
    # The same vector in a value's 3D form (a value with gd3): Vector3 in Godot's 3D view axes
    # (x right, y up, z toward the viewer), which are device space's; no flip.
    "game_vec3": ("Vec3", "Vector3", "Vector3.ZERO"),
    "string": ("std::string", "String", '""'),
}
# The Packed*Array GDScript uses for an array of a scalar.
PACKED = {
    "int": "PackedInt32Array",
    "int64": "PackedInt64Array",
    "uint8": "PackedByteArray",
    "uint16": "PackedInt32Array",
    "uint32": "PackedInt64Array",
    "uint64": "PackedInt64Array",
    "float": "PackedFloat64Array",
    "float32": "PackedFloat32Array",
    "vec2": "PackedVector2Array",
    "vec2f": "PackedVector2Array",
    "game_vec2": "PackedVector2Array",
    "game_vec3": "PackedVector3Array",
    "vec3": "PackedVector3Array",
    "vec3f": "PackedVector3Array",
    "string": "PackedStringArray",
}
INTEGER_BITS = {"int": 32, "int64": 64, "uint8": 8, "uint16": 16, "uint32": 32, "uint64": 64}
VECTORS = {"vec2", "vec3", "vec2f", "vec3f", "game_vec2", "game_vec3"}
TRANSFERS = ("reliable", "unreliable", "unreliable_ordered")
PEERS = ("any", "server")
FIELD_KEYS = {
    "type", "doc", "unit", "min", "max", "default", "max_count", "max_length", "nonzero",
    "finite", "fixed", "zero_means", "gd_bounds",
}


class SchemaError(Exception):
    pass


@dataclass
class Type:
    """A field's type: kind is "scalar", "enum" or "value"; container is "", "array" or
    "optional"."""

    kind: str
    name: str
    container: str = ""
    ref: object = None  # the Enum or Value for those kinds

    def canonical(self):
        inner = self.name if self.kind != "value" else self.ref.canonical()
        if self.kind == "enum":
            inner = "enum(" + ",".join(self.ref.values) + ")"
        return f"{self.container}<{inner}>" if self.container else inner


@dataclass
class Field:
    name: str
    type: Type
    doc: str = ""
    unit: str = ""
    min: object = None
    max: object = None
    default: object = None
    max_count: object = None  # int or a constant's name
    max_length: int = 0
    nonzero: bool = False
    finite: bool = True
    fixed: bool = False  # arrays: always max_count items (C++ std::array)
    zero_means: str = ""  # numbers: 0 is allowed besides [min, max], and means this
    gd_bounds: bool = False  # numbers: GDScript gets <FIELD>_MIN and <FIELD>_MAX constants
    count_limit_value: int = 0  # arrays: max_count as a number
    min_ref: str = ""  # the constant min or max names ("-MAX_GAIN"), when it names one
    max_ref: str = ""

    def count_limit(self, schema_set):
        if isinstance(self.max_count, str):
            return schema_set.constants[self.max_count].value
        return self.max_count


@dataclass
class Constant:
    name: str
    value: object
    doc: str
    file: object = None
    cpp_type: str = ""  # C++: its type when not size_t (integers) or double (floats)


@dataclass
class Enum:
    name: str
    values: list
    doc: str
    gd: str
    file: object = None
    labels: list = None  # words for people, one a value (C++ *_LABELS, GDScript *_LABELS)
    index_suffix: str = ""  # C++: a plain enum of array indices, NORMAL_FORCE for "_FORCE"


@dataclass
class Value:
    name: str
    gd: str
    doc: str
    realtime: bool
    fields: list
    file: object = None
    settings: bool = False  # a renderer's or the servo's settings
    message: object = None  # a network message's Message, None for other values
    # gd3: the value's 3D form (its game vectors as Vector3), a GDScript class of its own that
    # C++ reads into the same struct; twin_of: on that form, the value it is the form of.
    twin: object = None
    twin_of: object = None
    _canonical: str = None

    def canonical(self):
        if self._canonical is None:
            parts = [f"{f.name}:{f.type.canonical()}" for f in self.fields]
            self._canonical = self.name + "{" + ",".join(parts) + "}"
        return self._canonical

    @property
    def schema_id(self):
        """FNV-1a (32 bits) of the canonical layout: names and types, nested values included,
        so any change to the layout changes the id."""
        h = 0x811C9DC5
        for byte in self.canonical().encode("utf-8"):
            h = ((h ^ byte) * 0x01000193) & 0xFFFFFFFF
        return h


@dataclass
class Message:
    """How a network message travels: its channel (and the constant that names it), transfer
    mode, words for people, and whether only the server sends it and only the server takes
    it."""

    channel: int
    channel_ref: str
    transfer: str
    label: str
    from_server: bool
    to_server: bool


@dataclass
class SchemaFile:
    path: str  # project-relative
    doc: str
    cpp: str  # project-relative header path, or ""
    gdscript: str  # project-relative folder, or ""
    gd_constants: str
    cpp_includes: list
    gd_extends: str = ""
    constants: list = field(default_factory=list)
    enums: list = field(default_factory=list)
    values: list = field(default_factory=list)


class SchemaSet:
    def __init__(self):
        self.files = []
        self.constants = {}
        self.enums = {}
        self.values = {}

    def value_by_gd(self, gd_name):
        return next((v for v in self.values.values() if v.gd == gd_name), None)


SCHEMA_ROOTS = ["gdextension/src", "addons", "game"]
TYPE = re.compile(r"^(?:(array|optional)<(\w+)>|(\w+))$")


def find_schema_files(root):
    found = []
    for top in SCHEMA_ROOTS:
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(".schema.toml"):
                    found.append(os.path.relpath(os.path.join(folder, name), root))
    return found


def load(root):
    schema_set = SchemaSet()
    raw = {}
    for path in find_schema_files(root):
        with open(os.path.join(root, path), "rb") as f:
            try:
                data = tomllib.load(f)
            except tomllib.TOMLDecodeError as error:
                raise SchemaError(f"{path}: {error}") from error
        head = data.get("schema", {})
        folder = os.path.dirname(path)
        sf = SchemaFile(
            path=path,
            doc=head.get("doc", "").strip(),
            cpp=os.path.join(folder, head["cpp"]) if "cpp" in head else "",
            gdscript=head.get("gdscript", ""),
            gd_constants=head.get("gd_constants", ""),
            cpp_includes=list(head.get("cpp_includes", [])),
            gd_extends=head.get("gd_extends", ""),
        )
        for name, spec in data.get("constants", {}).items():
            _unique(schema_set, name, path)
            constant = Constant(name, spec["value"], spec.get("doc", "").strip(), sf, spec.get("cpp_type", ""))
            schema_set.constants[name] = constant
            sf.constants.append(constant)
        for name, spec in data.get("enums", {}).items():
            _unique(schema_set, name, path)
            enum = Enum(name, list(spec["values"]), spec.get("doc", "").strip(), spec.get("gd", name), sf,
                        spec.get("labels"), spec.get("index_suffix", ""))
            if enum.labels is not None and len(enum.labels) != len(enum.values):
                raise SchemaError(f"{path}: enum {name} needs one label a value")
            schema_set.enums[name] = enum
            sf.enums.append(enum)
        for name, spec in data.get("values", {}).items():
            _unique(schema_set, name, path)
            value = Value(name, spec.get("gd", name), spec.get("doc", "").strip(),
                          bool(spec.get("realtime", False)), [], sf,
                          settings=bool(spec.get("settings", False)))
            schema_set.values[name] = value
            sf.values.append(value)
            raw[(path, name)] = spec
            if any(key in spec for key in MESSAGE_KEYS):
                value.message = _message(schema_set, sf, name, spec)
        if (sf.constants or sf.enums) and sf.gdscript and not sf.gd_constants:
            raise SchemaError(f"{path}: constants or enums need [schema] gd_constants")
        schema_set.files.append(sf)
    for sf in schema_set.files:
        for value in sf.values:
            spec = raw[(sf.path, value.name)]
            for field_name, fspec in spec.get("fields", {}).items():
                value.fields.append(_field(schema_set, sf.path, value, field_name, fspec))
            if not value.fields and value.message is None:
                raise SchemaError(f"{sf.path}: {value.name} has no fields")
    for sf in schema_set.files:
        for value in sf.values:
            _twin(value, raw)
    return schema_set


def _has_game_vec(value):
    return any(f.type.name == "game_vec2" or (f.type.kind == "value" and _has_game_vec(f.type.ref))
               for f in value.fields)


def _twin(value, raw):
    """value's 3D form (value.twin) when its schema names one (gd3), with each game_vec2 as a
    game_vec3 and each nested value as that value's own 3D form, made first."""
    gd3 = raw[(value.file.path, value.name)].get("gd3")
    if value.twin is not None or not gd3:
        return
    where = f"{value.file.path}: {value.name}"
    if not _has_game_vec(value):
        raise SchemaError(f"{where}: a 3D form (gd3) is for a value with game vectors")
    if not value.file.cpp or value.message is not None:
        raise SchemaError(f"{where}: only a value C++ reads has a 3D form (gd3)")
    fields = []
    for f in value.fields:
        t = f.type
        if t.kind == "value" and _has_game_vec(t.ref):
            _twin(t.ref, raw)
            if t.ref.twin is None:
                raise SchemaError(f"{where}.{f.name}: {t.ref.name} needs a 3D form (gd3) too")
            t = Type("value", t.ref.twin.name, t.container, t.ref.twin)
        elif t.name == "game_vec2":
            t = Type("scalar", "game_vec3", t.container)
        fields.append(replace(f, type=t))
    doc = value.doc + " Its 3D form: game vectors in Godot's 3D view axes (docs/values.md)."
    value.twin = Value(value.name + "3D", gd3, doc, value.realtime, fields, value.file, twin_of=value)


MESSAGE_KEYS = ("channel", "transfer", "label", "sender", "receiver")


def _message(schema_set, sf, name, spec):
    where = f"{sf.path}: {name}"
    if sf.cpp or not sf.gdscript:
        raise SchemaError(f"{where}: network messages are GDScript-only (no cpp, a gdscript folder)")
    if not sf.gd_constants:
        raise SchemaError(f"{where}: a file of network messages needs [schema] gd_constants (their tables)")
    if not sf.gd_extends:
        raise SchemaError(f"{where}: a file of network messages needs [schema] gd_extends")
    channel = spec.get("channel")
    channel_ref = ""
    if isinstance(channel, str):
        if channel not in schema_set.constants:
            raise SchemaError(f"{where}: channel names no constant ({channel})")
        channel_ref, channel = channel, schema_set.constants[channel].value
    if not isinstance(channel, int) or isinstance(channel, bool) or channel < 0:
        raise SchemaError(f"{where}: a message needs a channel (0 or more, or a constant's name)")
    if spec.get("transfer") not in TRANSFERS:
        raise SchemaError(f"{where}: transfer must be one of {list(TRANSFERS)}")
    if not spec.get("label"):
        raise SchemaError(f"{where}: a message needs a label (words for people)")
    for key in ("sender", "receiver"):
        if spec.get(key, "any") not in PEERS:
            raise SchemaError(f"{where}: {key} must be one of {list(PEERS)}")
    return Message(channel, channel_ref, spec["transfer"], spec["label"],
                   spec.get("sender", "any") == "server", spec.get("receiver", "any") == "server")


def _unique(schema_set, name, path):
    if name in schema_set.constants or name in schema_set.enums or name in schema_set.values:
        raise SchemaError(f"{path}: the name {name} is defined twice")


def _field(schema_set, path, value, name, spec):
    where = f"{path}: {value.name}.{name}"
    unknown = set(spec) - FIELD_KEYS
    if unknown:
        raise SchemaError(f"{where}: unknown keys {sorted(unknown)}")
    m = TYPE.match(spec.get("type", ""))
    if not m:
        raise SchemaError(f"{where}: type must be a name, array<name> or optional<name>")
    container = m.group(1) or ""
    type_name = m.group(2) or m.group(3)
    if type_name in SCALARS:
        kind, ref = "scalar", None
    elif type_name in schema_set.enums:
        kind, ref = "enum", schema_set.enums[type_name]
    elif type_name in schema_set.values:
        kind, ref = "value", schema_set.values[type_name]
    else:
        raise SchemaError(f"{where}: unknown type {type_name}")
    if container == "optional" and kind != "value":
        raise SchemaError(f"{where}: only a value can be optional")
    f = Field(name, Type(kind, type_name, container, ref), spec.get("doc", "").strip(),
              spec.get("unit", ""), spec.get("min"), spec.get("max"), spec.get("default"),
              spec.get("max_count"), spec.get("max_length", 0), spec.get("nonzero", False),
              spec.get("finite", True), spec.get("fixed", False), spec.get("zero_means", ""),
              spec.get("gd_bounds", False))
    for bound in ("min", "max"):
        given = getattr(f, bound)
        if isinstance(given, str):
            name = given.lstrip("-")
            if name not in schema_set.constants:
                raise SchemaError(f"{where}: {bound} names no constant ({given})")
            sign = -1 if given.startswith("-") else 1
            setattr(f, bound, sign * schema_set.constants[name].value)
            setattr(f, bound + "_ref", given)
    if isinstance(f.max_length, str):
        if f.max_length not in schema_set.constants:
            raise SchemaError(f"{where}: max_length names no constant ({f.max_length})")
        f.max_length = schema_set.constants[f.max_length].value
    if container == "array":
        limit = f.max_count
        if limit is None or (isinstance(limit, str) and limit not in schema_set.constants):
            raise SchemaError(f"{where}: an array needs max_count (a number or a constant)")
        f.count_limit_value = f.count_limit(schema_set)
    if kind == "scalar" and type_name in VECTORS and f.min is not None and value.file.cpp:
        raise SchemaError(f"{where}: a vector's min (its shortest length) is checked in GDScript only")
    if type_name == "string" and not f.max_length:
        raise SchemaError(f"{where}: a string needs max_length (bytes)")
    if value.realtime and kind == "value" and not f.type.ref.realtime:
        raise SchemaError(f"{where}: a realtime value holds only realtime values")
    if f.fixed and container != "array":
        raise SchemaError(f"{where}: only an array can be fixed")
    if f.default is not None and container:
        raise SchemaError(f"{where}: arrays and optionals have no default")
    if kind == "enum" and f.default is not None and f.default not in f.type.ref.values:
        raise SchemaError(f"{where}: default {f.default!r} is none of {f.type.ref.values}")
    return f


def snake(name):
    """HapticFrame -> haptic_frame; HapticFrame3D -> haptic_frame_3d (as Godot names node_3d)."""
    name = re.sub(r"(\d)D$", r"_\1d", name)
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()
