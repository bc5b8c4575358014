// Registering C++ classes and their methods with the engine's ClassDB. A method is bound
// once and then reachable both ways the engine calls: `call` (Variant arguments, from
// untyped GDScript; checked here and reported through the engine's call errors) and
// `ptrcall` (native slots, from statically typed GDScript; already checked by the engine).
#pragma once

#include <array>
#include <cstdio>
#include <exception>
#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "binding/type_info.h"

namespace gd {

// Everything a method needs to be described to the engine; the call paths are virtual.
class MethodBind {
public:
	virtual ~MethodBind() = default;
	virtual void call(void *p_instance, const GDExtensionConstVariantPtr *p_args,
			GDExtensionInt p_count, GDExtensionVariantPtr r_ret, GDExtensionCallError *r_error) const = 0;
	virtual void ptrcall(void *p_instance, const GDExtensionConstTypePtr *p_args,
			GDExtensionTypePtr r_ret) const = 0;

	std::string name;
	std::vector<std::string> arg_names;
	std::vector<VariantType> arg_types;
	std::vector<GDExtensionClassMethodArgumentMetadata> arg_metadata;
	std::vector<Variant> defaults; // for the last defaults.size() arguments
	bool has_return = false;
	bool is_const = false;
	VariantType return_type = VariantType::NIL;
	GDExtensionClassMethodArgumentMetadata return_metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;

protected:
	// Checks count and types of Variant arguments, filling r_args with each converted to its
	// parameter's type (defaults appended). False with r_error set if the call is invalid.
	bool prepare_arguments(const GDExtensionConstVariantPtr *p_args, GDExtensionInt p_count,
			Variant *r_args, GDExtensionCallError *r_error) const;
	void report_exception(const char *p_what) const;
};

template <typename C, typename F, typename R, typename... A>
class MethodBindT final : public MethodBind {
public:
	explicit MethodBindT(F p_fn) :
			fn_(p_fn) {}

	void call(void *p_instance, const GDExtensionConstVariantPtr *p_args, GDExtensionInt p_count,
			GDExtensionVariantPtr r_ret, GDExtensionCallError *r_error) const override {
		if (p_instance == nullptr) {
			r_error->error = GDEXTENSION_CALL_ERROR_INSTANCE_IS_NULL;
			return;
		}
		std::array<Variant, sizeof...(A) + 1> args; // +1: never a zero-length array
		if (!prepare_arguments(p_args, p_count, args.data(), r_error)) {
			return;
		}
		try {
			invoke_call(static_cast<C *>(p_instance), args.data(), r_ret,
					std::index_sequence_for<A...>{});
		} catch (const std::exception &e) {
			report_exception(e.what());
		} catch (...) {
			report_exception("unknown exception");
		}
	}

	void ptrcall(void *p_instance, const GDExtensionConstTypePtr *p_args,
			GDExtensionTypePtr r_ret) const override {
		try {
			invoke_ptr(static_cast<C *>(p_instance), p_args, r_ret, std::index_sequence_for<A...>{});
		} catch (const std::exception &e) {
			report_exception(e.what());
		} catch (...) {
			report_exception("unknown exception");
		}
	}

private:
	template <size_t... I>
	void invoke_call(C *p_self, const Variant *p_args, GDExtensionVariantPtr r_ret,
			std::index_sequence<I...>) const {
		if constexpr (std::is_void_v<R>) {
			(p_self->*fn_)(TypeInfo<BareType<A>>::from_variant(p_args[I])...);
		} else {
			const Variant ret = TypeInfo<BareType<R>>::to_variant(
					(p_self->*fn_)(TypeInfo<BareType<A>>::from_variant(p_args[I])...));
			// The engine hands us an initialised Variant to overwrite.
			api.variant_destroy(r_ret);
			api.variant_new_copy(r_ret, ret.ptr());
		}
	}

	template <size_t... I>
	void invoke_ptr(C *p_self, const GDExtensionConstTypePtr *p_args, GDExtensionTypePtr r_ret,
			std::index_sequence<I...>) const {
		if constexpr (std::is_void_v<R>) {
			(p_self->*fn_)(TypeInfo<BareType<A>>::from_ptr(p_args[I])...);
		} else {
			TypeInfo<BareType<R>>::to_ptr(r_ret,
					(p_self->*fn_)(TypeInfo<BareType<A>>::from_ptr(p_args[I])...));
		}
	}

	F fn_;
};

// Hands a bound method to the engine (and keeps it alive until unregister_classes()).
void register_method(const char *p_class, MethodBind *p_bind);
void register_integer_constant(const char *p_class, const char *p_enum, const char *p_name,
		int64_t p_value, bool p_bitfield);

// Passed to a class's static bind_methods(), like godot-cpp's ClassDB.
template <typename C>
class ClassBinder {
public:
	explicit ClassBinder(const char *p_class) :
			class_(p_class) {}

	template <typename R, typename... A>
	void bind_method(const char *p_name, R (C::*p_fn)(A...),
			std::initializer_list<const char *> p_arg_names = {},
			std::initializer_list<Variant> p_defaults = {}) {
		bind<R (C::*)(A...), R, A...>(p_name, p_fn, false, p_arg_names, p_defaults);
	}

	template <typename R, typename... A>
	void bind_method(const char *p_name, R (C::*p_fn)(A...) const,
			std::initializer_list<const char *> p_arg_names = {},
			std::initializer_list<Variant> p_defaults = {}) {
		bind<R (C::*)(A...) const, R, A...>(p_name, p_fn, true, p_arg_names, p_defaults);
	}

	// p_enum "" for a plain constant; p_bitfield for flags meant to be combined.
	void bind_constant(const char *p_enum, const char *p_name, int64_t p_value, bool p_bitfield = false) {
		register_integer_constant(class_, p_enum, p_name, p_value, p_bitfield);
	}

private:
	template <typename F, typename R, typename... A>
	void bind(const char *p_name, F p_fn, bool p_const, std::initializer_list<const char *> p_arg_names,
			std::initializer_list<Variant> p_defaults) {
		auto *mb = new MethodBindT<C, F, R, A...>(p_fn);
		mb->name = p_name;
		mb->is_const = p_const;
		mb->arg_types = { TypeInfo<BareType<A>>::type... };
		mb->arg_metadata = { TypeInfo<BareType<A>>::metadata... };
		for (const char *arg_name : p_arg_names) {
			mb->arg_names.emplace_back(arg_name);
		}
		while (mb->arg_names.size() < sizeof...(A)) {
			mb->arg_names.push_back("arg" + std::to_string(mb->arg_names.size()));
		}
		mb->defaults.assign(p_defaults.begin(), p_defaults.end());
		if constexpr (!std::is_void_v<R>) {
			mb->has_return = true;
			mb->return_type = TypeInfo<BareType<R>>::type;
			mb->return_metadata = TypeInfo<BareType<R>>::metadata;
		}
		register_method(class_, mb);
	}

	const char *class_;
};

// Common base of exposed classes: the engine deletes an instance through it.
class ExtensionObject {
public:
	virtual ~ExtensionObject() = default;
};

using CreateFunc = ExtensionObject *(*)();
void register_class_raw(const char *p_class, const char *p_parent, CreateFunc p_create);

// Registers C (which must derive ExtensionObject, have a default constructor and a static
// bind_methods(ClassBinder<C>&)) under p_class, deriving the engine class p_parent.
template <typename C>
void register_class(const char *p_class, const char *p_parent) {
	register_class_raw(p_class, p_parent, []() -> ExtensionObject * { return new C(); });
	ClassBinder<C> binder(p_class);
	C::bind_methods(binder);
}

// Unregisters every class in reverse order and frees the method binds.
void unregister_classes();

} // namespace gd
