#!/usr/bin/env bash
# The vehicle trial: Godot's demo 3d/truck_town (a checkout you give, nothing is downloaded)
# with this repository's haptics addon installed the README's way and the README's lines for a
# car added to its tow truck (a HapticVehicle3D under its VehicleBody3D, the steering read from
# it), run headless under a scripted driver (truck_town_driver.gd) on the real native library
# and its simulated device: prints a table of the rim force held in a turn, at full lock, in a
# crash against the chassis's contacts, on the grass, and landing off a ramp against the
# device's limit, and how many lines the install added to the demo's own files.
#
# Usage: tools/trials/truck_town.sh DEMO_DIR [--addon-rev REV]
#   DEMO_DIR      a copy of godot-demo-projects/3d/truck_town
#   --addon-rev   install the addon's scripts as they were at REV instead of the worktree's;
#                 the native library is always the worktree's bin/ (make import)
# The copy goes to .build/trial/truck_town-<rev|worktree>/ (rebuilt each run); the run's log
# is trial.log there.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT="$PWD"

usage() { sed -n '10,16p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
source tools/trials/trial-copy.sh
trial_args "$@"
[[ -f "$DEMO/project.godot" && -f "$DEMO/vehicles/vehicle.gd" && -f "$DEMO/vehicles/tow_truck.tscn" && -f "$DEMO/town/town_scene.tscn" ]] ||
	{ echo "trial: $DEMO is not the truck_town demo (project.godot, vehicles/vehicle.gd, vehicles/tow_truck.tscn, town/town_scene.tscn)" >&2; exit 2; }
trial_copy truck_town tools/trials/truck_town_driver.gd

# The addon README's install without the editor: its install script (the autoload, the plugin,
# the extension listed before the first import), then its input setting: the demo's own
# steering actions move the simulated hand.
if ! timeout 120 "$GODOT" --headless --path "$DEST" --script res://addons/haptics/editor/install.gd >"$DEST/install.log" 2>&1; then
	cat "$DEST/install.log" >&2
	echo "trial: the addon's install script failed (log: $DEST/install.log)" >&2
	exit 1
fi
cat >>"$DEST/project.godot" <<'CFG'

[haptics]

input/hand_actions=PackedStringArray("turn_left", "turn_right", "", "")
CFG
# The README's lines for a car, on the tow truck: the node under its VehicleBody3D with the
# demo's steer limit (vehicle.gd's STEER_LIMIT, 0.4 rad) as steer_lock, and vehicle.gd steering
# from it while the device steers (vehicle.gd is shared with the two cars without the node).
patch -s -p1 -d "$DEST" <<'PATCH'
--- a/vehicles/tow_truck.tscn
+++ b/vehicles/tow_truck.tscn
@@ -13,6 +13,7 @@
 [ext_resource type="AudioStream" uid="uid://dyq28bk7fqj44" path="res://vehicles/impact_4.wav" id="9_y8ei3"]
 [ext_resource type="Texture2D" uid="uid://yexl3pkv5tea" path="res://vehicles/particle_smoke.png" id="10_lfosv"]
 [ext_resource type="Texture2D" uid="uid://c6nommjyxiscs" path="res://vehicles/blob_shadow.png" id="11_5ul8v"]
+[ext_resource type="Script" path="res://addons/haptics/vehicle/haptic_vehicle_3d.gd" id="12_haptics"]
 
 [sub_resource type="BoxShape3D" id="BoxShape3D_0hbge"]
 size = Vector3(1.17624, 0.6963, 2.23996)
@@ -245,6 +246,10 @@
 [node name="TopDownCameraPosition" type="Marker3D" parent="Body" unique_id=302585488]
 transform = Transform3D(-1, 8.74228e-08, 0, 3.82137e-15, 4.37114e-08, 1, 8.74228e-08, 1, -4.37114e-08, 0.00169557, 15.7771, 0.0955178)
 
+[node name="HapticVehicle3D" type="Node" parent="Body"]
+script = ExtResource("12_haptics")
+steer_lock = 0.4
+
 [node name="ChainB1" type="RigidBody3D" parent="." unique_id=1651819882]
 transform = Transform3D(1, 0, 0, 0, 0.846248, -0.53279, 0, 0.53279, 0.846248, 0, 1.10846, -1.55698)
 
--- a/vehicles/vehicle.gd
+++ b/vehicles/vehicle.gd
@@ -82,7 +82,13 @@
 		# Apply analog brake factor for more subtle braking if not fully holding down the trigger.
 		engine_force *= Input.get_action_strength(&"reverse")
 
-	steering = move_toward(steering, _steer_target, STEER_SPEED * delta)
+	var wheel_device: HapticVehicle3D = get_node_or_null(^"HapticVehicle3D")
+	if wheel_device != null:
+		wheel_device.steers_with_device = wheel_device.device_steers()
+	if wheel_device != null and wheel_device.steers_with_device:
+		steering = wheel_device.get_steering_angle()
+	else:
+		steering = move_toward(steering, _steer_target, STEER_SPEED * delta)
 
 	previous_speed = linear_velocity.length()
 
PATCH
added=""
for file in project.godot vehicles/tow_truck.tscn vehicles/vehicle.gd; do
	n=$(diff "$DEMO/$file" "$DEST/$file" | grep -c '^>' || true)
	m=$(diff "$DEMO/$file" "$DEST/$file" | grep -c '^<' || true)
	added+="$file +$n -$m; "
done

trial_run "TRIAL|HapticVehicle3D" "TRIAL lines the install changed in the demo's files: ${added% }"
