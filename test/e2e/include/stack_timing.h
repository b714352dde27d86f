// The stack's timing as the end-to-end judges bound it, in one place (the fault tests each
// carried their own copy): config/tracking.yaml's scan_timeout and pose_timeout, one control
// period (20 Hz), a scan of the emulated TiM (15 Hz), and the driver's next command slot
// (min_command_interval 0.05 s, found by its 20 ms poll) that puts a zero on the wire.
#pragma once

namespace stack_timing {

inline constexpr double kScanTimeout = 0.5;         // [s] config/tracking.yaml scan_timeout
inline constexpr double kPoseTimeout = 0.5;         // [s] config/tracking.yaml pose_timeout
inline constexpr double kControlPeriod = 0.05;      // [s] the tracking loop at 20 Hz
inline constexpr double kScanPeriod = 1.0 / 15.0;   // [s] the TiM at 15 Hz
inline constexpr double kDriverSlot = 0.05 + 0.02;  // [s] min_command_interval + the driver's poll

}  // namespace stack_timing
