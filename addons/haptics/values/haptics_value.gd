class_name HapticsValue
extends RefCounted
## What every value generated from a schema is ([code]docs/values.md[/code]): typed
## properties and its bytes. Each class adds [code]SCHEMA_ID[/code] (its layout's id), a static
## [code]decode()[/code] and [code]read_from()[/code], and overrides the two methods below.


## This value's bytes: its layout id, then its fields.
func encode() -> PackedByteArray:
	push_error("HapticsValue.encode: %s does not override it." % (get_script() as Script).resource_path)
	return PackedByteArray()


## Writes the fields, in order (also as part of a value that holds this one).
func write_to(_writer: HapticsWireWriter) -> void:
	push_error("HapticsValue.write_to: %s does not override it." % (get_script() as Script).resource_path)
