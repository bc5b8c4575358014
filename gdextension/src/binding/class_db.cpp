#include "binding/class_db.h"

#include <memory>

#include "binding/call_check.h"
#include "binding/log.h"

namespace gd {

namespace {

constexpr uint32_t PROPERTY_USAGE_DEFAULT = 6;
constexpr uint32_t PROPERTY_USAGE_NIL_IS_VARIANT = 1u << 17;

struct ClassRecord {
	std::string class_name;
	std::unique_ptr<StringName> name;
	std::unique_ptr<StringName> parent;
	CreateFunc create = nullptr;
	std::vector<std::unique_ptr<MethodBind>> methods;
};

// Owned here from registration to unregistration; read-only while the engine runs.
std::vector<std::unique_ptr<ClassRecord>> &classes() {
	static std::vector<std::unique_ptr<ClassRecord>> records;
	return records;
}

ClassRecord *find_class(const char *p_class) {
	for (auto &record : classes()) {
		if (record->class_name == p_class) {
			return record.get();
		}
	}
	return nullptr;
}

GDExtensionObjectPtr create_instance(void *p_userdata, GDExtensionBool /*p_notify*/) {
	auto *record = static_cast<ClassRecord *>(p_userdata);
	GDExtensionObjectPtr object = api.classdb_construct_object2(record->parent->ptr());
	ExtensionObject *instance = record->create();
	api.object_set_instance(object, record->name->ptr(), instance);
	return object;
}

void free_instance(void * /*p_userdata*/, GDExtensionClassInstancePtr p_instance) {
	delete static_cast<ExtensionObject *>(p_instance);
}

void call_trampoline(void *p_method, GDExtensionClassInstancePtr p_instance,
		const GDExtensionConstVariantPtr *p_args, GDExtensionInt p_count, GDExtensionVariantPtr r_ret,
		GDExtensionCallError *r_error) {
	static_cast<const MethodBind *>(p_method)->call(p_instance, p_args, p_count, r_ret, r_error);
}

void ptrcall_trampoline(void *p_method, GDExtensionClassInstancePtr p_instance,
		const GDExtensionConstTypePtr *p_args, GDExtensionTypePtr r_ret) {
	static_cast<const MethodBind *>(p_method)->ptrcall(p_instance, p_args, r_ret);
}

// Property descriptions hold engine strings that must outlive the registration call only.
struct PropertyDescription {
	StringName name;
	StringName class_name{ "" };
	String hint_string;
	GDExtensionPropertyInfo info{};

	PropertyDescription(const std::string &p_name, VariantType p_type) :
			name(p_name) {
		info.type = static_cast<GDExtensionVariantType>(p_type);
		info.name = name.ptr();
		info.class_name = class_name.ptr();
		info.hint = 0;
		info.hint_string = hint_string.ptr();
		info.usage = PROPERTY_USAGE_DEFAULT;
		if (p_type == VariantType::NIL) {
			info.usage |= PROPERTY_USAGE_NIL_IS_VARIANT;
		}
	}
};

} // namespace

bool MethodBind::prepare_arguments(const GDExtensionConstVariantPtr *p_args,
		GDExtensionInt p_count, Variant *r_args, GDExtensionCallError *r_error) const {
	const CallCheck check = check_argument_count(static_cast<int64_t>(arg_types.size()),
			static_cast<int64_t>(defaults.size()), p_count);
	if (check.error != CallCheck::OK) {
		r_error->error = check.error == CallCheck::TOO_MANY ? GDEXTENSION_CALL_ERROR_TOO_MANY_ARGUMENTS
															: GDEXTENSION_CALL_ERROR_TOO_FEW_ARGUMENTS;
		r_error->expected = static_cast<int32_t>(check.expected);
		return false;
	}
	const size_t first_default = arg_types.size() - defaults.size();
	for (size_t i = 0; i < arg_types.size(); ++i) {
		// The engine's Variant is layout-identical to ours: read its argument in place.
		const Variant &source = static_cast<GDExtensionInt>(i) < p_count
				? *reinterpret_cast<const Variant *>(p_args[i])
				: defaults[i - first_default];
		if (arg_types[i] == VariantType::NIL) { // a Variant parameter takes anything
			r_args[i] = source;
			continue;
		}
		if (!source.convert_strict(arg_types[i], r_args[i])) {
			r_error->error = GDEXTENSION_CALL_ERROR_INVALID_ARGUMENT;
			r_error->argument = static_cast<int32_t>(i);
			r_error->expected = static_cast<int32_t>(arg_types[i]);
			return false;
		}
	}
	return true;
}

void MethodBind::report_exception(const char *p_what) const {
	print_error("Internal error in '" + name + "': " + p_what, __func__, __FILE__, __LINE__);
}

void register_class_raw(const char *p_class, const char *p_parent, CreateFunc p_create) {
	auto record = std::make_unique<ClassRecord>();
	record->class_name = p_class;
	record->name = std::make_unique<StringName>(p_class);
	record->parent = std::make_unique<StringName>(p_parent);
	record->create = p_create;

	GDExtensionClassCreationInfo5 info{};
	info.is_virtual = 0;
	info.is_abstract = 0;
	info.is_exposed = 1;
	info.is_runtime = 0;
	info.create_instance_func = &create_instance;
	info.free_instance_func = &free_instance;
	info.class_userdata = record.get();
	api.classdb_register_extension_class5(api.library, record->name->ptr(), record->parent->ptr(),
			&info);
	classes().push_back(std::move(record));
}

void register_method(const char *p_class, MethodBind *p_bind) {
	std::unique_ptr<MethodBind> bind(p_bind);
	ClassRecord *record = find_class(p_class);
	if (record == nullptr) {
		print_error(std::string("register_method: unknown class ") + p_class, __func__, __FILE__,
				__LINE__);
		return;
	}

	StringName method_name(bind->name);
	std::vector<std::unique_ptr<PropertyDescription>> args;
	std::vector<GDExtensionPropertyInfo> arg_infos;
	for (size_t i = 0; i < bind->arg_types.size(); ++i) {
		args.push_back(std::make_unique<PropertyDescription>(bind->arg_names[i], bind->arg_types[i]));
		arg_infos.push_back(args.back()->info);
	}
	PropertyDescription return_info("", bind->return_type);
	std::vector<GDExtensionVariantPtr> default_ptrs;
	for (Variant &value : bind->defaults) {
		default_ptrs.push_back(value.ptr());
	}
	std::vector<GDExtensionClassMethodArgumentMetadata> metadata = bind->arg_metadata;

	GDExtensionClassMethodInfo info{};
	info.name = method_name.ptr();
	info.method_userdata = bind.get();
	info.call_func = &call_trampoline;
	info.ptrcall_func = &ptrcall_trampoline;
	info.method_flags = static_cast<uint32_t>(GDEXTENSION_METHOD_FLAGS_DEFAULT);
	if (bind->is_const) {
		info.method_flags |= static_cast<uint32_t>(GDEXTENSION_METHOD_FLAG_CONST);
	}
	info.has_return_value = bind->has_return ? 1 : 0;
	info.return_value_info = &return_info.info;
	info.return_value_metadata = bind->return_metadata;
	info.argument_count = static_cast<uint32_t>(arg_infos.size());
	info.arguments_info = arg_infos.data();
	info.arguments_metadata = metadata.data();
	info.default_argument_count = static_cast<uint32_t>(default_ptrs.size());
	info.default_arguments = default_ptrs.data();
	api.classdb_register_extension_class_method(api.library, record->name->ptr(), &info);
	record->methods.push_back(std::move(bind));
}

void register_integer_constant(const char *p_class, const char *p_enum, const char *p_name,
		int64_t p_value, bool p_bitfield) {
	ClassRecord *record = find_class(p_class);
	if (record == nullptr) {
		return;
	}
	StringName enum_name(p_enum);
	StringName constant_name(p_name);
	api.classdb_register_extension_class_integer_constant(api.library, record->name->ptr(),
			enum_name.ptr(), constant_name.ptr(), p_value, p_bitfield ? 1 : 0);
}

void unregister_classes() {
	auto &records = classes();
	while (!records.empty()) {
		api.classdb_unregister_extension_class(api.library, records.back()->name->ptr());
		records.pop_back();
	}
}

} // namespace gd
