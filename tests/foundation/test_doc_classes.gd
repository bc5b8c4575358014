extends TestSuite
## The class reference in gdextension/doc_classes (shown in the editor's help) against what
## the extension registers: every method with its return and parameter types, every constant
## with its value and enum, nothing documented that does not exist.

const DOC_DIR: String = "res://gdextension/doc_classes"


func test_each_native_class_has_its_reference() -> void:
	for native_class: StringName in [&"HapticsSystem", &"DurableFile"]:
		var doc: Dictionary = _read(native_class)
		assert_false(doc.is_empty(), "%s.xml is readable" % native_class)
		if doc.is_empty():
			continue
		assert_eq(doc["inherits"], ClassDB.get_parent_class(native_class))
		var methods: Dictionary = doc["methods"]
		var bound: Dictionary[String, PackedStringArray] = {}
		for method: Dictionary in ClassDB.class_get_method_list(native_class, true):
			var returned: Dictionary = method["return"]
			var returns: int = returned["type"]
			var signature: PackedStringArray = [
				"-> void" if returns == TYPE_NIL else "-> " + type_string(returns)
			]
			for arg: Dictionary in method["args"]:
				var arg_type: int = arg["type"]
				signature.append("%s: %s" % [arg["name"], type_string(arg_type)])
			bound[method["name"]] = signature
		for method_name: String in bound:
			assert_true(
				methods.has(method_name), "%s.%s is documented" % [native_class, method_name]
			)
			if methods.has(method_name):
				assert_eq(methods[method_name], bound[method_name], "signature of %s" % method_name)
		for method_name: String in methods:
			assert_true(bound.has(method_name), "%s.%s exists" % [native_class, method_name])
		var constants: Dictionary = doc["constants"]
		var registered: PackedStringArray = ClassDB.class_get_integer_constant_list(
			native_class, true
		)
		assert_eq(constants.size(), registered.size(), "%s constants" % native_class)
		for constant_name: String in registered:
			assert_true(constants.has(constant_name), "%s is documented" % constant_name)
			if constants.has(constant_name):
				var value: int = ClassDB.class_get_integer_constant(native_class, constant_name)
				assert_eq(constants[constant_name]["value"], value, constant_name)
				assert_eq(
					constants[constant_name]["enum"],
					String(
						ClassDB.class_get_integer_constant_enum(native_class, constant_name, true)
					),
					"enum of %s" % constant_name
				)


# {inherits, methods: {name: ["-> Return", "param: Type", ...]}, constants: {name: {value, enum}}}
func _read(native_class: StringName) -> Dictionary:
	var parser: XMLParser = XMLParser.new()
	if parser.open("%s/%s.xml" % [DOC_DIR, native_class]) != OK:
		return {}
	var doc: Dictionary = {"inherits": "", "methods": {}, "constants": {}}
	var method: String = ""
	while parser.read() == OK:
		if parser.get_node_type() != XMLParser.NODE_ELEMENT:
			continue
		match parser.get_node_name():
			"class":
				doc["inherits"] = parser.get_named_attribute_value_safe("inherits")
			"method":
				method = parser.get_named_attribute_value("name")
				doc["methods"][method] = PackedStringArray()
			"return", "param":
				var signature: PackedStringArray = doc["methods"][method]
				var type_name: String = parser.get_named_attribute_value("type")
				if parser.get_node_name() == "return":
					signature.append("-> " + type_name)
				else:
					signature.append(
						"%s: %s" % [parser.get_named_attribute_value("name"), type_name]
					)
				doc["methods"][method] = signature
			"constant":
				doc["constants"][parser.get_named_attribute_value("name")] = {
					"value": parser.get_named_attribute_value("value").to_int(),
					"enum": parser.get_named_attribute_value_safe("enum"),
				}
	return doc
