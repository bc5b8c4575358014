class_name HapticsWireWriter
extends RefCounted
## Appends a value's bytes in the wire format of [code]docs/values.md[/code]: the generated
## value classes' [code]encode()[/code] and [code]write_to()[/code] call it, field by field.
## Little-endian; a string is a u16 byte count and UTF-8, an array a u32 count and its items.

var _bytes: PackedByteArray = PackedByteArray()
var _size: int = 0


func _init(schema_id: int) -> void:
	_bytes.resize(64)
	integer(schema_id, 4)


## The bytes written so far.
func bytes() -> PackedByteArray:
	return _bytes.slice(0, _size)


func boolean(value: bool) -> void:
	u8(1 if value else 0)


func u8(value: int) -> void:
	_reserve(1)
	_bytes.encode_u8(_size, value & 0xFF)
	_size += 1


## [param value] in [param width] bytes (1, 2, 4 or 8), two's complement.
func integer(value: int, width: int) -> void:
	_reserve(width)
	match width:
		1:
			_bytes.encode_u8(_size, value & 0xFF)
		2:
			_bytes.encode_u16(_size, value & 0xFFFF)
		4:
			_bytes.encode_u32(_size, value & 0xFFFFFFFF)
		_:
			_bytes.encode_s64(_size, value)
	_size += width


## An array's item count (u32).
func count(value: int) -> void:
	integer(value, 4)


func f32(value: float) -> void:
	_reserve(4)
	_bytes.encode_float(_size, value)
	_size += 4


func f64(value: float) -> void:
	_reserve(8)
	_bytes.encode_double(_size, value)
	_size += 8


func vec2(value: Vector2) -> void:
	f64(value.x)
	f64(value.y)


func vec2f(value: Vector2) -> void:
	f32(value.x)
	f32(value.y)


func vec3(value: Vector3) -> void:
	f64(value.x)
	f64(value.y)
	f64(value.z)


func vec3f(value: Vector3) -> void:
	f32(value.x)
	f32(value.y)
	f32(value.z)


func text(value: String) -> void:
	var utf8: PackedByteArray = value.to_utf8_buffer()
	integer(utf8.size(), 2)
	_reserve(utf8.size())
	for i: int in utf8.size():
		_bytes[_size + i] = utf8[i]
	_size += utf8.size()


func _reserve(extra: int) -> void:
	if _size + extra > _bytes.size():
		_bytes.resize(maxi(_bytes.size() * 2, _size + extra))
