#pragma once

// A 3-vector of doubles for device space (metres, newtons, metres per second). Doubles
// because the servo integrates and filters at up to 4 kHz, where float rounding in a
// low-cutoff IIR is audible as drift; the frame stays trivially copyable either way.

#include <cmath>

namespace haptics {

struct Vec3 {
	double x = 0.0;
	double y = 0.0;
	double z = 0.0;

	constexpr Vec3() = default;
	constexpr Vec3(double p_x, double p_y, double p_z) :
			x(p_x), y(p_y), z(p_z) {}

	constexpr Vec3 operator+(const Vec3 &p_other) const { return { x + p_other.x, y + p_other.y, z + p_other.z }; }
	constexpr Vec3 operator-(const Vec3 &p_other) const { return { x - p_other.x, y - p_other.y, z - p_other.z }; }
	constexpr Vec3 operator-() const { return { -x, -y, -z }; }
	constexpr Vec3 operator*(double p_scale) const { return { x * p_scale, y * p_scale, z * p_scale }; }
	constexpr Vec3 operator/(double p_scale) const { return { x / p_scale, y / p_scale, z / p_scale }; }
	constexpr Vec3 &operator+=(const Vec3 &p_other) {
		x += p_other.x;
		y += p_other.y;
		z += p_other.z;
		return *this;
	}
	constexpr Vec3 &operator-=(const Vec3 &p_other) {
		x -= p_other.x;
		y -= p_other.y;
		z -= p_other.z;
		return *this;
	}
	constexpr Vec3 &operator*=(double p_scale) {
		x *= p_scale;
		y *= p_scale;
		z *= p_scale;
		return *this;
	}
	constexpr bool operator==(const Vec3 &p_other) const = default;
};

constexpr Vec3 operator*(double p_scale, const Vec3 &p_v) {
	return p_v * p_scale;
}

constexpr double dot(const Vec3 &p_a, const Vec3 &p_b) {
	return p_a.x * p_b.x + p_a.y * p_b.y + p_a.z * p_b.z;
}

constexpr Vec3 cross(const Vec3 &p_a, const Vec3 &p_b) {
	return { p_a.y * p_b.z - p_a.z * p_b.y, p_a.z * p_b.x - p_a.x * p_b.z, p_a.x * p_b.y - p_a.y * p_b.x };
}

constexpr double length_squared(const Vec3 &p_v) {
	return dot(p_v, p_v);
}

inline double length(const Vec3 &p_v) {
	return std::sqrt(length_squared(p_v));
}

inline bool is_finite(const Vec3 &p_v) {
	return std::isfinite(p_v.x) && std::isfinite(p_v.y) && std::isfinite(p_v.z);
}

// Returns the zero vector for vectors shorter than p_epsilon instead of dividing by ~0.
inline Vec3 normalized_or_zero(const Vec3 &p_v, double p_epsilon = 1e-9) {
	const double len = length(p_v);
	return len > p_epsilon ? p_v / len : Vec3{};
}

} // namespace haptics
