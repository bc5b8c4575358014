#include "binding/dictionary_reader.h"

#include <set>
#include <utility>

#include "binding/log.h"
#include "binding/version.h"

namespace haptics::binding {

DictionaryReader::DictionaryReader(const gd::Dictionary &p_dictionary, std::string p_path) :
		dictionary_(p_dictionary), path_(std::move(p_path)) {}

bool DictionaryReader::has(const char *p_key) const {
	if (dictionary_.has(gd::Variant(p_key))) {
		return true;
	}
	for (size_t i = 0; i < old_key_count_; ++i) {
		const auto &[old_key, key] = old_keys_[i];
		if (may_have_old_key(i) && std::string_view(key) == p_key && dictionary_.has(gd::Variant(old_key))) {
			return true;
		}
	}
	return false;
}

namespace {

// Without the indices of list entries: "frame.contacts[3]" -> "frame.contacts".
std::string without_indices(const std::string &p_path) {
	std::string out;
	int depth = 0;
	for (const char c : p_path) {
		depth += c == '[' ? 1 : 0;
		if (depth == 0) {
			out += c;
		}
		depth -= c == ']' ? 1 : 0;
	}
	return out;
}

} // namespace

void warn_old_key(const std::string &p_old_name, const std::string &p_new_name) {
	static std::set<std::string> warned; // Main thread only, like every binding call.
	if (warned.insert(p_old_name).second) {
		HAPTICS_WARNING(p_old_name + " is deprecated: use " + p_new_name + " (the old name is accepted until " +
				OLD_KEYS_REMOVED_IN + ")");
	}
}

void DictionaryReader::accept_old_key(const char *p_old_key, const char *p_key) {
	if (old_key_count_ < old_keys_.size()) {
		old_keys_[old_key_count_++] = { p_old_key, p_key };
	}
}

bool DictionaryReader::fetch(const char *p_key, gd::VariantType p_type, const char *p_expected,
		bool p_required, gd::Variant &r_value) {
	gd::Variant value;
	bool found = dictionary_.get(gd::Variant(p_key), value);
	for (size_t i = 0; i < old_key_count_ && !found; ++i) {
		const auto &[old_key, key] = old_keys_[i];
		if (may_have_old_key(i) && std::string_view(key) == p_key && dictionary_.get(gd::Variant(old_key), value)) {
			found = true;
			const std::string base = without_indices(path_);
			warn_old_key(base + "." + old_key, base + "." + key);
			p_key = old_key; // Errors name the key as the caller spelled it.
		}
	}
	if (!found) {
		if (p_required) {
			error_ = path_ + "." + p_key + ": missing (expected " + p_expected + ")";
			return false;
		}
		return true;
	}
	if (!value.convert_strict(p_type, r_value)) {
		error_ = path_ + "." + p_key + ": expected " + p_expected + ", got " +
				variant_type_name(value.get_type());
		return false;
	}
	return true;
}

bool DictionaryReader::read_number(const char *p_key, double &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::FLOAT, "a number", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_float();
	}
	return true;
}

bool DictionaryReader::read_bool(const char *p_key, bool &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::BOOL, "a bool", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_bool();
	}
	return true;
}

bool DictionaryReader::read_int(const char *p_key, int64_t &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::INT, "an int", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_int();
	}
	return true;
}

bool DictionaryReader::read_vector2(const char *p_key, gd::Vector2 &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::VECTOR2, "a Vector2", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_vector2();
	}
	return true;
}

bool DictionaryReader::read_vector3(const char *p_key, gd::Vector3 &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::VECTOR3, "a Vector3", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_vector3();
	}
	return true;
}

bool DictionaryReader::read_string(const char *p_key, std::string &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::STRING, "a String", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = value.as_string();
	}
	return true;
}

bool DictionaryReader::read_array(const char *p_key, gd::Array &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::ARRAY, "an Array", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = gd::Array(std::move(value));
	}
	return true;
}

bool DictionaryReader::read_dictionary(const char *p_key, gd::Dictionary &r_value, bool p_required) {
	gd::Variant value;
	if (!fetch(p_key, gd::VariantType::DICTIONARY, "a Dictionary", p_required, value)) {
		return false;
	}
	if (!value.is_nil()) {
		r_value = gd::Dictionary(std::move(value));
	}
	return true;
}

bool DictionaryReader::only_keys(std::initializer_list<const char *> p_allowed) {
	const gd::Array keys = dictionary_.keys();
	for (int64_t i = 0; i < keys.size(); ++i) {
		const gd::Variant key = keys.get(i);
		const std::string name = key.as_string();
		bool known = false;
		for (const char *allowed : p_allowed) {
			known = known || name == allowed;
		}
		for (size_t r = 0; r < old_key_count_; ++r) {
			if (name == old_keys_[r].first) {
				known = true;
				old_present_ |= 1u << r;
			}
		}
		if (!known) {
			std::string list;
			for (const char *allowed : p_allowed) {
				list += list.empty() ? "" : ", ";
				list += allowed;
			}
			error_ = path_ + ": unknown key '" + name + "' (known: " + list + ")";
			return false;
		}
	}
	keys_scanned_ = true;
	return true;
}

int64_t name_index(const std::string &p_name, std::span<const char *const> p_names) {
	for (size_t i = 0; i < p_names.size(); ++i) {
		if (p_name == p_names[i]) {
			return static_cast<int64_t>(i);
		}
	}
	return -1;
}

std::string variant_type_name(gd::VariantType p_type) {
	switch (p_type) {
		case gd::VariantType::NIL:
			return "null";
		case gd::VariantType::BOOL:
			return "bool";
		case gd::VariantType::INT:
			return "int";
		case gd::VariantType::FLOAT:
			return "float";
		case gd::VariantType::STRING:
			return "String";
		case gd::VariantType::VECTOR2:
			return "Vector2";
		case gd::VariantType::VECTOR3:
			return "Vector3";
		case gd::VariantType::STRING_NAME:
			return "StringName";
		case gd::VariantType::DICTIONARY:
			return "Dictionary";
		case gd::VariantType::ARRAY:
			return "Array";
		default:
			return "type " + std::to_string(static_cast<int>(p_type));
	}
}

} // namespace haptics::binding
