class_name HapticsValue
extends RefCounted
## What every value generated from a schema is ([code]docs/values.md[/code]): typed
## properties and its bytes. Each class adds [code]SCHEMA_ID[/code] (its layout's id), a static
## [code]decode()[/code] and [code]read_from()[/code], and overrides the two methods below.


## This value's bytes: its layout id, then its fields.
func encode() -> PackedByteArray:
	push_error("HapticsValue.encode: %s does not override it." % self)
	return PackedByteArray()


## Writes the fields, in order (also as part of a value that holds this one).
func write_to(_writer: HapticsWireWriter) -> void:
	push_error("HapticsValue.write_to: %s does not override it." % self)


## The name of [param value] in enum [param choices] as settings files and the wire's
## documentation spell it ([code]HapticMovementFacts.ContactModel[/code], 1 →
## [code]"paper_sum"[/code]); "" when it is none of them.
static func choice_name(choices: Dictionary, value: int) -> String:
	var key: Variant = choices.find_key(value)
	return "" if key == null else str(key).to_lower()


## The value named [param name] in enum [param choices] ([code]"paper_sum"[/code] → 1);
## -1 when it names none of them.
static func choice_value(choices: Dictionary, name: String) -> int:
	var value: int = choices.get(name.to_upper(), -1)
	return value if name == name.to_lower() else -1


## The names of enum [param choices], in order ([code]["per_contact", "paper_sum"][/code]).
static func choice_names(choices: Dictionary) -> PackedStringArray:
	var names: PackedStringArray = []
	for key: String in choices.keys():
		names.append(key.to_lower())
	return names
