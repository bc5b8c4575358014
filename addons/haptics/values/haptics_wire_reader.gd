class_name HapticsWireReader
extends RefCounted
## Reads a value's bytes in the wire format of [code]docs/values.md[/code] for the generated
## value classes' [code]decode()[/code] and [code]read_from()[/code], checking every bound
## and every limit the schema gives. The first failure sticks: later reads return zeros, and
## [method finish] reports it, naming the field by its path
## ([code]HapticFrame.contacts[2].normal: zero length: a direction is needed[/code]). Bytes
## from anywhere (a hostile network peer included) are safe to read: nothing here prints an
## engine error.

## Why the last failed decode failed; empty when the last decode succeeded.
static var last_error: String = ""

## Whether a read has failed.
var failed: bool = false
## Why, naming the field.
var error: String = ""

var _bytes: PackedByteArray = PackedByteArray()
var _offset: int = 0
var _path: PackedStringArray = PackedStringArray()


func _init(bytes: PackedByteArray, schema_id: int, what: String) -> void:
	_bytes = bytes
	_path.append(what)
	var id: int = integer(&"", 4, false)
	if not failed and id != schema_id:
		_fail(
			(
				"layout %08x is not this one (%08x): the sender's scripts or library are another version"
				% [id, schema_id]
			)
		)


## Whether every byte was read without a failure; records [member last_error].
func finish() -> bool:
	if not failed and _offset != _bytes.size():
		_fail("%d bytes more than the value holds" % (_bytes.size() - _offset))
	last_error = error
	return not failed


func boolean(field: StringName) -> bool:
	var byte: int = _u8()
	if byte > 1:
		_fail("%d is not a bool (0 or 1)" % byte, field)
	return byte == 1


## [param width] bytes (1, 2, 4 or 8), signed or not, within [param low] and [param high].
func integer(
	field: StringName,
	width: int,
	signed: bool,
	low: int = -0x7FFFFFFFFFFFFFFF,
	high: int = 0x7FFFFFFFFFFFFFFF
) -> int:
	if not _need(width):
		return 0
	var value: int = 0
	match width:
		1:
			value = _bytes.decode_s8(_offset) if signed else _bytes.decode_u8(_offset)
		2:
			value = _bytes.decode_s16(_offset) if signed else _bytes.decode_u16(_offset)
		4:
			value = _bytes.decode_s32(_offset) if signed else _bytes.decode_u32(_offset)
		_:
			value = _bytes.decode_s64(_offset) if signed else _bytes.decode_u64(_offset)
	_offset += width
	if value < low or value > high:
		_fail("%d is outside [%d, %d]" % [value, low, high], field)
	return value


## A binary64 within [param low] and [param high] (or 0 when [param zero_ok]: 0 means a default).
func f64(
	field: StringName,
	low: float = -INF,
	high: float = INF,
	finite: bool = true,
	zero_ok: bool = false
) -> float:
	return _float(8, field, low, high, finite, zero_ok)


## A binary32, checked as [method f64] checks.
func f32(
	field: StringName,
	low: float = -INF,
	high: float = INF,
	finite: bool = true,
	zero_ok: bool = false
) -> float:
	return _float(4, field, low, high, finite, zero_ok)


## Two binary64 components; [param nonzero], the length bounds and [param finite] are checked
## on the vector as a whole.
func vec2(
	field: StringName,
	nonzero: bool = false,
	max_length: float = INF,
	finite: bool = true,
	min_length: float = 0.0
) -> Vector2:
	var v: Vector3 = _vector(2, 8, field, nonzero, max_length, finite, min_length)
	return Vector2(v.x, v.y)


## Two binary32 components, checked as [method vec2] checks.
func vec2f(
	field: StringName,
	nonzero: bool = false,
	max_length: float = INF,
	finite: bool = true,
	min_length: float = 0.0
) -> Vector2:
	var v: Vector3 = _vector(2, 4, field, nonzero, max_length, finite, min_length)
	return Vector2(v.x, v.y)


## Three binary64 components, checked as [method vec2] checks.
func vec3(
	field: StringName,
	nonzero: bool = false,
	max_length: float = INF,
	finite: bool = true,
	min_length: float = 0.0
) -> Vector3:
	var v: Vector3 = _vector(3, 8, field, nonzero, max_length, finite, min_length)
	return v


## Three binary32 components, checked as [method vec2] checks.
func vec3f(
	field: StringName,
	nonzero: bool = false,
	max_length: float = INF,
	finite: bool = true,
	min_length: float = 0.0
) -> Vector3:
	var v: Vector3 = _vector(3, 4, field, nonzero, max_length, finite, min_length)
	return v


## At most [param max_bytes] bytes of well-formed UTF-8.
func text(field: StringName, max_bytes: int) -> String:
	var size: int = integer(field, 2, false)
	if failed:
		return ""
	if size > max_bytes:
		_fail("%d bytes of text, at most %d" % [size, max_bytes], field)
		return ""
	if not _need(size):
		return ""
	var utf8: PackedByteArray = _bytes.slice(_offset, _offset + size)
	_offset += size
	if not _valid_utf8(utf8):
		_fail("not UTF-8 text", field)
		return ""
	return utf8.get_string_from_utf8()


## An enum's index, below [param value_count].
func enum_index(field: StringName, value_count: int) -> int:
	var index: int = _u8()
	if index >= value_count:
		_fail("%d is none of the %d values" % [index, value_count], field)
		return 0
	return index


## An array's item count, at most [param most] (0 once failed).
func count(field: StringName, most: int) -> int:
	var items: int = integer(field, 4, false)
	if items > most:
		_fail("%d items, at most %d" % [items, most], field)
	return 0 if failed else items


## A fixed array's item count, which must be exactly [param expected] (0 once failed).
func exact_count(field: StringName, expected: int) -> int:
	var items: int = integer(field, 4, false)
	if items != expected:
		_fail("%d items, exactly %d" % [items, expected], field)
	return 0 if failed else items


## Whether an optional value follows.
func present(field: StringName) -> bool:
	var byte: int = _u8()
	if byte > 1:
		_fail("%d is not a presence flag (0 or 1)" % byte, field)
	return byte == 1


## Names a nested value in the messages until [method leave].
func enter(field: StringName) -> void:
	_path.append("." + field)


## Names an item of an array in the messages until [method leave].
func enter_item(field: StringName, index: int) -> void:
	_path.append(".%s[%d]" % [field, index])


func leave() -> void:
	_path.remove_at(_path.size() - 1)


func _float(
	width: int, field: StringName, low: float, high: float, finite: bool, zero_ok: bool
) -> float:
	if not _need(width):
		return 0.0
	var value: float = _bytes.decode_double(_offset) if width == 8 else _bytes.decode_float(_offset)
	_offset += width
	if not (zero_ok and value == 0.0):
		_check_number(field, value, low, high, finite)
	return value


func _u8() -> int:
	if not _need(1):
		return 0
	var value: int = _bytes.decode_u8(_offset)
	_offset += 1
	return value


func _need(size: int) -> bool:
	if failed:
		return false
	if _bytes.size() - _offset < size:
		_fail("the bytes end early (%d of %d read)" % [_offset, _bytes.size()])
		return false
	return true


func _check_number(field: StringName, value: float, low: float, high: float, finite: bool) -> void:
	if finite and not is_finite(value):
		_fail("not finite (%s)" % value, field)
	elif value < low or value > high:
		_fail("%s is outside [%s, %s]" % [value, low, high], field)


func _vector(
	components: int,
	width: int,
	field: StringName,
	nonzero: bool,
	max_length: float,
	finite: bool,
	min_length: float
) -> Vector3:
	var value: Vector3 = Vector3.ZERO
	for i in components:
		value[i] = _float(width, &"", -INF, INF, false, false)
	_check_vector(field, value, nonzero, max_length, finite, min_length)
	return value


func _check_vector(
	field: StringName,
	value: Vector3,
	nonzero: bool,
	max_length: float,
	finite: bool,
	min_length: float = 0.0
) -> void:
	if finite and not value.is_finite():
		_fail("not finite %s" % value, field)
	elif nonzero and not value.length() > 1e-9:
		_fail("zero length: a direction is needed", field)
	elif value.length() > max_length:
		_fail("length %s is above %s" % [value.length(), max_length], field)
	elif value.length() < min_length:
		_fail("length %s is below %s" % [value.length(), min_length], field)


func _fail(reason: String, field: StringName = &"") -> void:
	if failed:
		return
	failed = true
	var where: String = "".join(_path) + ("." + field if not field.is_empty() else "")
	error = "%s: %s" % [where, reason]


# Well-formed UTF-8 (RFC 3629): checked before the engine decodes it, which would print an
# error for each malformed sequence.
static func _valid_utf8(utf8: PackedByteArray) -> bool:
	var i: int = 0
	while i < utf8.size():
		var lead: int = utf8[i]
		var extra: int = 0
		var code: int = 0
		if lead < 0x80:
			i += 1
			continue
		if lead & 0xE0 == 0xC0:
			extra = 1
			code = lead & 0x1F
		elif lead & 0xF0 == 0xE0:
			extra = 2
			code = lead & 0x0F
		elif lead & 0xF8 == 0xF0:
			extra = 3
			code = lead & 0x07
		else:
			return false
		if i + extra >= utf8.size():
			return false
		for k: int in range(1, extra + 1):
			if utf8[i + k] & 0xC0 != 0x80:
				return false
			code = (code << 6) | (utf8[i + k] & 0x3F)
		var smallest: int = [0, 0x80, 0x800, 0x10000][extra]
		if code < smallest or code > 0x10FFFF or (code >= 0xD800 and code <= 0xDFFF):
			return false
		i += extra + 1
	return true
