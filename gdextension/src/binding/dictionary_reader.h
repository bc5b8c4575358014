// Reads typed fields out of a GDScript Dictionary, naming the offending field in the error
// ("frame.contacts[2].stiffness: expected a number, got String"). Unknown keys are errors
// too, so a typo in GDScript is reported instead of silently ignored.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>

#include "binding/containers.h"

namespace haptics::binding {

class DictionaryReader {
public:
	// p_path names the dictionary in messages, e.g. "frame" or "frame.contacts[2]".
	DictionaryReader(const gd::Dictionary &p_dictionary, std::string p_path);

	// Each returns false (with error() set) if the key is present with the wrong type or,
	// for required reads, missing. An absent optional key leaves r_value untouched.
	bool read_number(const char *p_key, double &r_value, bool p_required = false);
	bool read_bool(const char *p_key, bool &r_value, bool p_required = false);
	bool read_int(const char *p_key, int64_t &r_value, bool p_required = false);
	bool read_vector2(const char *p_key, gd::Vector2 &r_value, bool p_required = false);
	bool read_vector3(const char *p_key, gd::Vector3 &r_value, bool p_required = false);
	bool read_string(const char *p_key, std::string &r_value, bool p_required = false); // Or a StringName.
	bool read_array(const char *p_key, gd::Array &r_value, bool p_required = false);
	bool read_dictionary(const char *p_key, gd::Dictionary &r_value, bool p_required = false);
	bool has(const char *p_key) const; // Also under its old name.

	// False (with error() set) if the dictionary holds a key outside p_allowed (or their
	// old names, see accept_old_key).
	bool only_keys(std::initializer_list<const char *> p_allowed);
	// p_old_key was renamed p_key: when p_key is absent, reads of it take p_old_key instead,
	// with a deprecation warning (once per process and key). At most four per reader.
	void accept_old_key(const char *p_old_key, const char *p_key);

	const std::string &error() const { return error_; }
	const std::string &path() const { return path_; }

private:
	bool fetch(const char *p_key, gd::VariantType p_type, const char *p_expected, bool p_required,
			gd::Variant &r_value);

	const gd::Dictionary &dictionary_;
	std::string path_;
	std::string error_;
	// (old, new); a fixed array: frames are read at 50 Hz and need no allocation for this.
	std::array<std::pair<const char *, const char *>, 4> old_keys_{};
	size_t old_key_count_ = 0;
	// After only_keys() has seen every key: which old keys are there (bit i: old_keys_[i]),
	// so reads never look up an old name that is absent.
	bool keys_scanned_ = false;
	uint32_t old_present_ = 0;

	bool may_have_old_key(size_t p_index) const { return !keys_scanned_ || (old_present_ & (1u << p_index)) != 0; }
};

// "X is deprecated, use Y" through the engine's warning printer, once per process for each
// p_old_name (a name without indices, e.g. "frame.contacts.damping").
void warn_old_key(const std::string &p_old_name, const std::string &p_new_name);

// The position of p_name in p_names (an enum's names in value order), or -1.
int64_t name_index(const std::string &p_name, std::span<const char *const> p_names);

// The name of a Variant type as GDScript prints it ("float", "Vector2"...).
std::string variant_type_name(gd::VariantType p_type);

} // namespace haptics::binding
