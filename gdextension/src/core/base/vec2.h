#pragma once

// A 2-vector of doubles for the constraint renderer, which works in the plane of the maze
// (maze units, e.g. pixels) and the device's x-y plane (metres). Doubles for the same reason
// as Vec3: the proxy is integrated for hours at 1 kHz and must not drift through a wall by
// float rounding.

#include <cmath>

namespace haptics {

struct Vec2 {
	double x = 0.0;
	double y = 0.0;

	constexpr Vec2() = default;
	constexpr Vec2(double p_x, double p_y) :
			x(p_x), y(p_y) {}

	constexpr Vec2 operator+(const Vec2 &p_other) const { return { x + p_other.x, y + p_other.y }; }
	constexpr Vec2 operator-(const Vec2 &p_other) const { return { x - p_other.x, y - p_other.y }; }
	constexpr Vec2 operator-() const { return { -x, -y }; }
	constexpr Vec2 operator*(double p_scale) const { return { x * p_scale, y * p_scale }; }
	constexpr Vec2 operator/(double p_scale) const { return { x / p_scale, y / p_scale }; }
	constexpr Vec2 &operator+=(const Vec2 &p_other) {
		x += p_other.x;
		y += p_other.y;
		return *this;
	}
	constexpr bool operator==(const Vec2 &p_other) const = default;
};

constexpr Vec2 operator*(double p_scale, const Vec2 &p_v) {
	return p_v * p_scale;
}

constexpr double dot(const Vec2 &p_a, const Vec2 &p_b) {
	return p_a.x * p_b.x + p_a.y * p_b.y;
}

// z of the 3D cross product: > 0 when p_b is counter-clockwise from p_a.
constexpr double cross(const Vec2 &p_a, const Vec2 &p_b) {
	return p_a.x * p_b.y - p_a.y * p_b.x;
}

// p_v turned 90 degrees counter-clockwise.
constexpr Vec2 perpendicular(const Vec2 &p_v) {
	return { -p_v.y, p_v.x };
}

constexpr double length_squared(const Vec2 &p_v) {
	return dot(p_v, p_v);
}

inline double length(const Vec2 &p_v) {
	return std::sqrt(length_squared(p_v));
}

inline bool is_finite(const Vec2 &p_v) {
	return std::isfinite(p_v.x) && std::isfinite(p_v.y);
}

} // namespace haptics
