#pragma once

// The cable of a device that exists in software (the simulated device, and in development
// builds each backend's model of its hardware): the game can pull it to exercise disconnect
// handling. Pulled, the device's servo calls report DeviceIo::DISCONNECTED and open() fails,
// until it is plugged back. Game thread, also while the servo runs.

namespace haptics {

class SoftwareCable {
public:
	virtual void set_plugged(bool p_plugged) = 0;

protected:
	~SoftwareCable() = default; // Owned by its device, never deleted through this.
};

} // namespace haptics
