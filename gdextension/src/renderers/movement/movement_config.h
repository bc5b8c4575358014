#pragma once

// The movement renderer's settings: its part of section "force_model" (the contact law; the
// input vector's and the impacts' keys are the servo's, core/servo/servo_config.h) and
// section "smoothing". Each field's range, unit and key are in its row of the field table
// (movement_config_fields.cpp).

#include "core/render/frame.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

// How the movement renderer turns several contacts into one normal force and friction
// (force_model.h has the equations of both).
enum class ContactModel : int32_t {
	// Each contact pushes back only against the part of the input pressing into it, with its
	// own material: a floor and a wall give exactly the wall's push-back for a horizontal
	// push, and pulling away from a contact gives no force. The default, for games.
	PER_CONTACT = 0,
	// The paper's literal model: one normal, the normalised sum of the contact normals, and
	// F_n = -k p whatever the sign of p (it pulls toward a contact the input points away
	// from). For replicating the paper.
	PAPER_SUM = 1,
};
// Their names, in enum order (what set_config also accepts).
inline constexpr const char *CONTACT_MODEL_NAMES[] = { "per_contact", "paper_sum" };

struct ForceModelConfig {
	// "g" of W = m g (n.d) d. Not Earth's 9.81: it is the gain from the game's masses to felt
	// weight, and 9.81 would saturate a 3.3 N device with a 1 kg crate.
	double gravity_n_per_kg = 1.0;
	ContactModel contact_model = ContactModel::PER_CONTACT;
	// PER_CONTACT only: a contact's friction fades in linearly while the input presses into
	// the contacts by less than this (input units), and is the paper's -b r from there on.
	// Without it friction would jump from 0 to b |r| as the hand crosses a floor's plane.
	// 0 switches friction fully on at any pressing.
	double friction_engage = 0.05;
	ContactMaterial default_contact; // For contacts without a material.
};

struct SmoothingConfig {
	// Off, the continuous sum goes straight through (the 50 Hz staircase is felt). On, a
	// 2nd-order Butterworth low-pass (smoothing_filter.h says why that filter).
	bool enabled = true;
	double cutoff_hz = 13.0;
};

struct MovementConfig {
	ForceModelConfig force_model;
	SmoothingConfig smoothing;
};

static_assert(std::is_trivially_copyable_v<MovementConfig>);

} // namespace haptics
