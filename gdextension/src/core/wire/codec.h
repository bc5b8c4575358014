#pragma once

// Encoding and decoding any schema value (a *.gen.h struct: it has SCHEMA_ID, NAME and
// visit()) in the wire format of docs/values.md, checking on the way in every limit its
// schema gives: a decoded value is one whose fields are all within them. The encoding starts
// with the value's SCHEMA_ID, so bytes of another layout (a library and scripts out of step)
// are refused by name. Game thread only: it allocates.

#include "core/base/bounded_array.h"
#include "core/base/field_spec.h"
#include "core/base/fixed_string.h"
#include "core/base/status.h"
#include "core/base/vec2.h"
#include "core/base/vec3.h"
#include "core/wire/wire_io.h"

#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace haptics {

template <typename T>
concept SchemaValue = requires {
	T::SCHEMA_ID;
	T::NAME;
};

// A value with a 3D form (its schema's gd3): the same fields under SCHEMA_ID_3D, its game
// vectors as a 3D game's (GameSpace::SPACE).
template <typename T>
concept HasSpaceForm = SchemaValue<T> && requires {
	T::SCHEMA_ID_3D;
};

namespace wire_detail {

template <typename T>
struct Sequence : std::false_type {};
template <typename T, size_t N>
struct Sequence<BoundedArray<T, N>> : std::true_type {
	static constexpr size_t CAPACITY = N;
};
template <typename T>
struct Sequence<std::vector<T>> : std::true_type {
	static constexpr size_t CAPACITY = UINT32_MAX;
};

template <typename T>
struct Fixed : std::false_type {};
template <typename T, size_t N>
struct Fixed<std::array<T, N>> : std::true_type {
	static constexpr size_t COUNT = N;
};

template <typename T>
struct Text : std::false_type {};
template <size_t N>
struct Text<FixedString<N>> : std::true_type {};

template <typename T>
struct Optional : std::false_type {};
template <typename T>
struct Optional<std::optional<T>> : std::true_type {};

void check_number(WireReader &r_reader, const FieldSpec &p_spec, double p_value);
void check_vector(WireReader &r_reader, const FieldSpec &p_spec, const Vec3 &p_value);

template <typename T>
void write(WireWriter &r_writer, const FieldSpec &p_spec, const T &p_value) {
	if constexpr (SchemaValue<T>) {
		T::visit(p_value, [&](const FieldSpec &p_field, const auto &p_member) { write(r_writer, p_field, p_member); });
	} else if constexpr (std::is_same_v<T, bool>) {
		r_writer.u8(p_value ? 1 : 0);
	} else if constexpr (std::is_enum_v<T>) {
		r_writer.u8(static_cast<uint8_t>(p_value));
	} else if constexpr (std::is_integral_v<T>) {
		using U = std::make_unsigned_t<T>;
		if constexpr (sizeof(T) == 1) {
			r_writer.u8(static_cast<U>(p_value));
		} else if constexpr (sizeof(T) == 2) {
			r_writer.u16(static_cast<U>(p_value));
		} else if constexpr (sizeof(T) == 4) {
			r_writer.u32(static_cast<U>(p_value));
		} else {
			r_writer.u64(static_cast<U>(p_value));
		}
	} else if constexpr (std::is_floating_point_v<T>) {
		if (p_spec.wire == Wire::F32) {
			r_writer.f32(static_cast<float>(p_value));
		} else {
			r_writer.f64(static_cast<double>(p_value));
		}
	} else if constexpr (std::is_same_v<T, Vec2>) {
		write(r_writer, p_spec, p_value.x);
		write(r_writer, p_spec, p_value.y);
	} else if constexpr (std::is_same_v<T, Vec3>) {
		if (p_spec.wire == Wire::GAME_VEC2 && r_writer.space == GameSpace::PLANE) {
			r_writer.f64(p_value.x);
			r_writer.f64(-p_value.y);
		} else if (p_spec.wire == Wire::GAME_VEC2) {
			r_writer.f64(p_value.x);
			r_writer.f64(p_value.y);
			r_writer.f64(p_value.z);
		} else {
			write(r_writer, p_spec, p_value.x);
			write(r_writer, p_spec, p_value.y);
			write(r_writer, p_spec, p_value.z);
		}
	} else if constexpr (std::is_same_v<T, std::string>) {
		r_writer.text(p_value);
	} else if constexpr (Text<T>::value) {
		r_writer.text(p_value.str());
	} else if constexpr (Optional<T>::value) {
		r_writer.u8(p_value.has_value() ? 1 : 0);
		if (p_value.has_value()) {
			write(r_writer, p_spec, *p_value);
		}
	} else if constexpr (Sequence<T>::value || Fixed<T>::value) {
		r_writer.u32(static_cast<uint32_t>(p_value.size()));
		for (const auto &item : p_value) {
			write(r_writer, p_spec, item);
		}
	} else {
		static_assert(sizeof(T) == 0, "no wire form for this member type");
	}
}

template <typename T>
void read(WireReader &r_reader, const FieldSpec &p_spec, T &r_value) {
	if constexpr (SchemaValue<T>) {
		T::visit(r_value, [&](const FieldSpec &p_field, auto &r_member) {
			r_reader.enter(p_field.name);
			read(r_reader, p_field, r_member);
			r_reader.leave();
		});
	} else if constexpr (std::is_same_v<T, bool>) {
		const uint8_t byte = r_reader.u8();
		if (byte > 1) {
			r_reader.fail(StatusCode::INVALID_ARGUMENT, "%u is not a bool (0 or 1)", unsigned(byte));
		}
		r_value = byte == 1;
	} else if constexpr (std::is_enum_v<T>) {
		const uint8_t index = r_reader.u8();
		if (index >= EnumInfo<T>::COUNT) {
			r_reader.fail(StatusCode::OUT_OF_RANGE, "%u is none of the %u values", unsigned(index),
					unsigned(EnumInfo<T>::COUNT));
		}
		r_value = static_cast<T>(index < EnumInfo<T>::COUNT ? index : 0);
	} else if constexpr (std::is_integral_v<T>) {
		uint64_t bits = 0;
		if constexpr (sizeof(T) == 1) {
			bits = r_reader.u8();
		} else if constexpr (sizeof(T) == 2) {
			bits = r_reader.u16();
		} else if constexpr (sizeof(T) == 4) {
			bits = r_reader.u32();
		} else {
			bits = r_reader.u64();
		}
		r_value = static_cast<T>(static_cast<std::make_unsigned_t<T>>(bits));
		check_number(r_reader, p_spec, static_cast<double>(r_value));
	} else if constexpr (std::is_floating_point_v<T>) {
		r_value = static_cast<T>(p_spec.wire == Wire::F32 ? double(r_reader.f32()) : r_reader.f64());
		check_number(r_reader, p_spec, static_cast<double>(r_value));
	} else if constexpr (std::is_same_v<T, Vec2>) {
		const bool f32 = p_spec.wire == Wire::F32;
		r_value.x = f32 ? double(r_reader.f32()) : r_reader.f64();
		r_value.y = f32 ? double(r_reader.f32()) : r_reader.f64();
		check_vector(r_reader, p_spec, Vec3(r_value.x, r_value.y, 0.0));
	} else if constexpr (std::is_same_v<T, Vec3>) {
		if (p_spec.wire == Wire::GAME_VEC2 && r_reader.space == GameSpace::PLANE) {
			const double x = r_reader.f64();
			const double y = r_reader.f64();
			r_value = Vec3(x, -y, 0.0);
		} else if (p_spec.wire == Wire::GAME_VEC2) {
			r_value.x = r_reader.f64();
			r_value.y = r_reader.f64();
			r_value.z = r_reader.f64();
		} else {
			const bool f32 = p_spec.wire == Wire::F32;
			r_value.x = f32 ? double(r_reader.f32()) : r_reader.f64();
			r_value.y = f32 ? double(r_reader.f32()) : r_reader.f64();
			r_value.z = f32 ? double(r_reader.f32()) : r_reader.f64();
		}
		check_vector(r_reader, p_spec, r_value);
	} else if constexpr (std::is_same_v<T, std::string>) {
		r_value = r_reader.text(p_spec.max_count);
	} else if constexpr (Text<T>::value) {
		r_value.assign(r_reader.text(static_cast<uint32_t>(T::CAPACITY)));
	} else if constexpr (Fixed<T>::value) {
		const uint32_t count = r_reader.u32();
		if (r_reader.ok() && count != Fixed<T>::COUNT) {
			r_reader.fail(StatusCode::INVALID_ARGUMENT, "%u items, exactly %zu", unsigned(count), Fixed<T>::COUNT);
			return;
		}
		for (size_t i = 0; i < Fixed<T>::COUNT && r_reader.ok(); ++i) {
			r_reader.enter_item(i);
			read(r_reader, p_spec, r_value[i]);
			r_reader.leave();
		}
	} else if constexpr (Optional<T>::value) {
		const uint8_t present = r_reader.u8();
		if (present > 1) {
			r_reader.fail(StatusCode::INVALID_ARGUMENT, "%u is not a presence flag (0 or 1)", unsigned(present));
		}
		r_value.reset();
		if (present == 1 && r_reader.ok()) {
			r_value.emplace();
			read(r_reader, p_spec, *r_value);
		}
	} else if constexpr (Sequence<T>::value) {
		const uint32_t count = r_reader.u32();
		const size_t limit = std::min<size_t>(p_spec.max_count, Sequence<T>::CAPACITY);
		if (count > limit) {
			r_reader.fail(StatusCode::INVALID_ARGUMENT, "%u items, at most %zu", unsigned(count), limit);
			return;
		}
		r_value.clear();
		for (uint32_t i = 0; i < count && r_reader.ok(); ++i) {
			typename std::remove_cvref_t<decltype(*r_value.begin())> item{};
			r_reader.enter_item(i);
			read(r_reader, p_spec, item);
			r_reader.leave();
			r_value.push_back(item);
		}
	} else {
		static_assert(sizeof(T) == 0, "no wire form for this member type");
	}
}

} // namespace wire_detail

// In r_writer.space's form: a value without a 3D form is written in its only one.
template <SchemaValue T>
void encode_into(WireWriter &r_writer, const T &p_value) {
	if constexpr (HasSpaceForm<T>) {
		r_writer.u32(r_writer.space == GameSpace::SPACE ? T::SCHEMA_ID_3D : T::SCHEMA_ID);
	} else {
		r_writer.space = GameSpace::PLANE;
		r_writer.u32(T::SCHEMA_ID);
	}
	wire_detail::write(r_writer, FieldSpec{}, p_value);
}

template <SchemaValue T>
std::vector<uint8_t> encode(const T &p_value, GameSpace p_space = GameSpace::PLANE) {
	WireWriter writer;
	writer.space = p_space;
	encode_into(writer, p_value);
	return writer.take();
}

// Either form of a value that has two; r_space (when given) says which it was. r_value and
// r_space are written only when the whole value decodes: a refused value changes nothing.
template <SchemaValue T>
Status decode(std::span<const uint8_t> p_bytes, T &r_value, GameSpace *r_space = nullptr) {
	WireReader reader(p_bytes, T::NAME);
	const uint32_t id = reader.u32();
	if constexpr (HasSpaceForm<T>) {
		reader.space = id == T::SCHEMA_ID_3D ? GameSpace::SPACE : GameSpace::PLANE;
	}
	if (reader.ok() && id != T::SCHEMA_ID && reader.space == GameSpace::PLANE) {
		reader.fail(StatusCode::INVALID_ARGUMENT,
				"got layout %08x, not this value's (%08x): another value, or scripts and library out of step", unsigned(id),
				unsigned(T::SCHEMA_ID));
	}
	T value{};
	wire_detail::read(reader, FieldSpec{}, value);
	const Status status = reader.finish();
	if (status) {
		r_value = value;
		if (r_space != nullptr) {
			*r_space = reader.space;
		}
	}
	return status;
}

// The limits of p_value's schema, checked as a decode would (for values made in C++).
// A value with a 3D form is checked in it, depth included.
template <SchemaValue T>
Status check_fields(const T &p_value) {
	T copy{};
	return decode(encode(p_value, HasSpaceForm<T> ? GameSpace::SPACE : GameSpace::PLANE), copy);
}

} // namespace haptics
