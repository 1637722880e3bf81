// The HID usages feel's report descriptor names: the standard pages it uses and the feel
// vendor page. Private to the protocol library.
//
// A usage is written here in its 32-bit "extended" form, page << 16 | id, the form a
// 4-byte HID Usage item carries; the descriptor writer splits it back into Usage Page and
// Usage items.
//
// The PID numbers are those of the USB "Device Class Definition for Physical Interface
// Devices (PID)" 1.0, usage page 0x0F (the same numbers the Linux hid-pidff driver and
// DirectInput's HID driver look for). The vendor numbers are feel's own and are frozen by
// kProtocolVendorRevision: a change is a new revision.
#pragma once

#include <cstdint>

#include "feel/effect_type.hpp"

namespace feel::protocol::usage {

inline constexpr uint16_t kPageGenericDesktop = 0x01;
inline constexpr uint16_t kPageButton = 0x09;
inline constexpr uint16_t kPageOrdinal = 0x0A;
inline constexpr uint16_t kPagePid = 0x0F;
inline constexpr uint16_t kPageVendor = 0xFF00;  // the first vendor-defined page

[[nodiscard]] constexpr uint32_t extended(uint16_t page, uint16_t id) noexcept {
    return static_cast<uint32_t>(page) << 16 | id;
}
[[nodiscard]] constexpr uint16_t page_of(uint32_t usage) noexcept {
    return static_cast<uint16_t>(usage >> 16);
}
[[nodiscard]] constexpr uint16_t id_of(uint32_t usage) noexcept {
    return static_cast<uint16_t>(usage & 0xFFFFu);
}

// Generic Desktop page (HID Usage Tables 1.x, §4).
namespace gd {
inline constexpr uint32_t kPointer = extended(kPageGenericDesktop, 0x01);
inline constexpr uint32_t kJoystick = extended(kPageGenericDesktop, 0x04);
inline constexpr uint32_t kX = extended(kPageGenericDesktop, 0x30);
inline constexpr uint32_t kY = extended(kPageGenericDesktop, 0x31);
inline constexpr uint32_t kZ = extended(kPageGenericDesktop, 0x32);
inline constexpr uint32_t kRx = extended(kPageGenericDesktop, 0x33);
inline constexpr uint32_t kRy = extended(kPageGenericDesktop, 0x34);
inline constexpr uint32_t kRz = extended(kPageGenericDesktop, 0x35);
inline constexpr uint32_t kHatSwitch = extended(kPageGenericDesktop, 0x39);
inline constexpr uint32_t kByteCount = extended(kPageGenericDesktop, 0x3B);  // PID Create New Effect
}  // namespace gd

// Ordinal page: Instance n (PID's Direction collection lists its angles as Ordinals).
[[nodiscard]] constexpr uint32_t ordinal(uint16_t n) noexcept { return extended(kPageOrdinal, n); }

[[nodiscard]] constexpr uint32_t button(uint16_t n) noexcept { return extended(kPageButton, n); }

// PID page 0x0F (PID 1.0, §5).
namespace pid {
constexpr uint32_t u(uint16_t id) noexcept { return extended(kPagePid, id); }
inline constexpr uint32_t kSetEffectReport = u(0x21);
inline constexpr uint32_t kEffectBlockIndex = u(0x22);
inline constexpr uint32_t kParameterBlockOffset = u(0x23);
inline constexpr uint32_t kEffectType = u(0x25);
inline constexpr uint32_t kEtConstantForce = u(0x26);
inline constexpr uint32_t kEtRamp = u(0x27);
inline constexpr uint32_t kEtCustomForceData = u(0x28);
inline constexpr uint32_t kEtSquare = u(0x30);
inline constexpr uint32_t kEtSine = u(0x31);
inline constexpr uint32_t kEtTriangle = u(0x32);
inline constexpr uint32_t kEtSawtoothUp = u(0x33);
inline constexpr uint32_t kEtSawtoothDown = u(0x34);
inline constexpr uint32_t kEtSpring = u(0x40);
inline constexpr uint32_t kEtDamper = u(0x41);
inline constexpr uint32_t kEtInertia = u(0x42);
inline constexpr uint32_t kEtFriction = u(0x43);
inline constexpr uint32_t kDuration = u(0x50);
inline constexpr uint32_t kSamplePeriod = u(0x51);
inline constexpr uint32_t kGain = u(0x52);
inline constexpr uint32_t kTriggerButton = u(0x53);
inline constexpr uint32_t kTriggerRepeatInterval = u(0x54);
inline constexpr uint32_t kAxesEnable = u(0x55);
inline constexpr uint32_t kDirectionEnable = u(0x56);
inline constexpr uint32_t kDirection = u(0x57);
inline constexpr uint32_t kSetEnvelopeReport = u(0x5A);
inline constexpr uint32_t kAttackLevel = u(0x5B);
inline constexpr uint32_t kAttackTime = u(0x5C);
inline constexpr uint32_t kFadeLevel = u(0x5D);
inline constexpr uint32_t kFadeTime = u(0x5E);
inline constexpr uint32_t kSetConditionReport = u(0x5F);
inline constexpr uint32_t kCpOffset = u(0x60);
inline constexpr uint32_t kPositiveCoefficient = u(0x61);
inline constexpr uint32_t kNegativeCoefficient = u(0x62);
inline constexpr uint32_t kPositiveSaturation = u(0x63);
inline constexpr uint32_t kNegativeSaturation = u(0x64);
inline constexpr uint32_t kDeadBand = u(0x65);
inline constexpr uint32_t kDownloadForceSample = u(0x66);
inline constexpr uint32_t kCustomForceDataReport = u(0x68);
inline constexpr uint32_t kCustomForceData = u(0x69);
inline constexpr uint32_t kSetCustomForceReport = u(0x6B);
inline constexpr uint32_t kCustomForceDataOffset = u(0x6C);
inline constexpr uint32_t kSampleCount = u(0x6D);
inline constexpr uint32_t kSetPeriodicReport = u(0x6E);
inline constexpr uint32_t kOffset = u(0x6F);
inline constexpr uint32_t kMagnitude = u(0x70);
inline constexpr uint32_t kPhase = u(0x71);
inline constexpr uint32_t kPeriod = u(0x72);
inline constexpr uint32_t kSetConstantForceReport = u(0x73);
inline constexpr uint32_t kSetRampForceReport = u(0x74);
inline constexpr uint32_t kRampStart = u(0x75);
inline constexpr uint32_t kRampEnd = u(0x76);
inline constexpr uint32_t kEffectOperationReport = u(0x77);
inline constexpr uint32_t kEffectOperation = u(0x78);
inline constexpr uint32_t kOpEffectStart = u(0x79);
inline constexpr uint32_t kOpEffectStartSolo = u(0x7A);
inline constexpr uint32_t kOpEffectStop = u(0x7B);
inline constexpr uint32_t kLoopCount = u(0x7C);
inline constexpr uint32_t kDeviceGainReport = u(0x7D);
inline constexpr uint32_t kDeviceGain = u(0x7E);
inline constexpr uint32_t kPidPoolReport = u(0x7F);
inline constexpr uint32_t kRamPoolSize = u(0x80);
inline constexpr uint32_t kSimultaneousEffectsMax = u(0x83);
inline constexpr uint32_t kPidBlockLoadReport = u(0x89);
inline constexpr uint32_t kBlockLoadStatus = u(0x8B);
inline constexpr uint32_t kBlockLoadSuccess = u(0x8C);
inline constexpr uint32_t kBlockLoadFull = u(0x8D);
inline constexpr uint32_t kBlockLoadError = u(0x8E);
inline constexpr uint32_t kPidBlockFreeReport = u(0x90);
inline constexpr uint32_t kPidStateReport = u(0x92);
inline constexpr uint32_t kEffectPlaying = u(0x94);
inline constexpr uint32_t kPidDeviceControlReport = u(0x95);
inline constexpr uint32_t kPidDeviceControl = u(0x96);
inline constexpr uint32_t kDcEnableActuators = u(0x97);
inline constexpr uint32_t kDcDisableActuators = u(0x98);
inline constexpr uint32_t kDcStopAllEffects = u(0x99);
inline constexpr uint32_t kDcDeviceReset = u(0x9A);
inline constexpr uint32_t kDcDevicePause = u(0x9B);
inline constexpr uint32_t kDcDeviceContinue = u(0x9C);
inline constexpr uint32_t kDevicePaused = u(0x9F);
inline constexpr uint32_t kActuatorsEnabled = u(0xA0);
inline constexpr uint32_t kSafetySwitch = u(0xA4);
inline constexpr uint32_t kActuatorOverrideSwitch = u(0xA5);
inline constexpr uint32_t kActuatorPower = u(0xA6);
inline constexpr uint32_t kStartDelay = u(0xA7);
inline constexpr uint32_t kDeviceManagedPool = u(0xA9);
inline constexpr uint32_t kSharedParameterBlocks = u(0xAA);
inline constexpr uint32_t kCreateNewEffectReport = u(0xAB);
inline constexpr uint32_t kRamPoolAvailable = u(0xAC);
}  // namespace pid

// feel's vendor page. Report (collection) usages reuse the report's id; field usages start
// at 0x100, grouped by the report that introduced them.
namespace vendor {
constexpr uint32_t u(uint16_t id) noexcept { return extended(kPageVendor, id); }
// Reports.
inline constexpr uint32_t kSetTextureReport = u(0x20);
inline constexpr uint32_t kSetWallReport = u(0x21);
inline constexpr uint32_t kSetBarrierReport = u(0x22);
inline constexpr uint32_t kSetSweepReport = u(0x23);
inline constexpr uint32_t kSetDynamicReport = u(0x24);
inline constexpr uint32_t kSetControlLawReport = u(0x25);
inline constexpr uint32_t kReflexReport = u(0x26);
inline constexpr uint32_t kIdfSettingsReport = u(0x27);
inline constexpr uint32_t kReportRateReport = u(0x28);
inline constexpr uint32_t kKeepAliveReport = u(0x29);
inline constexpr uint32_t kEffectStatusRequestReport = u(0x2A);
inline constexpr uint32_t kDeviceInfoReport = u(0x30);
inline constexpr uint32_t kCommandStatusReport = u(0x42);
inline constexpr uint32_t kDeviceStatusReport = u(0x43);
inline constexpr uint32_t kDynamicReportReport = u(0x44);
inline constexpr uint32_t kCommandErrorTextReport = u(0x45);
inline constexpr uint32_t kEffectStatesReport = u(0x46);

// Effect types PID 1.0 has no usage for (feel's EffectType beyond PID's twelve).
[[nodiscard]] constexpr uint32_t effect_type(uint8_t feel_type) noexcept {
    return u(static_cast<uint16_t>(0x80 + feel_type));
}

// Fields shared by many reports.
inline constexpr uint32_t kSequence = u(0x100);
inline constexpr uint32_t kHats = u(0x101);
// Set Effect.
inline constexpr uint32_t kIterations = u(0x110);
inline constexpr uint32_t kTriggerKind = u(0x111);
inline constexpr uint32_t kEffectAxis = u(0x112);
inline constexpr uint32_t kDirectionKind = u(0x113);
inline constexpr uint32_t kNoEnvelope = u(0x114);
inline constexpr uint32_t kDirectionVector = u(0x115);
// The microseconds below the millisecond of a PID time field (PID's fields carry whole
// milliseconds, the unit Linux's hid-pidff writes), one usage per time.
inline constexpr uint32_t kDurationFine = u(0x116);
inline constexpr uint32_t kRepeatIntervalFine = u(0x117);
inline constexpr uint32_t kStartDelayFine = u(0x119);
inline constexpr uint32_t kAttackTimeFine = u(0x11A);
inline constexpr uint32_t kFadeTimeFine = u(0x11B);
inline constexpr uint32_t kPeriodFine = u(0x11C);
// Set Condition, Set Wall.
inline constexpr uint32_t kOffsetMode = u(0x118);
// Set Custom Force, Custom Force Data, Download Force Sample.
inline constexpr uint32_t kChannels = u(0x120);
inline constexpr uint32_t kDataCount = u(0x121);
inline constexpr uint32_t kAxisCount = u(0x122);
// Texture.
inline constexpr uint32_t kPosRoughness = u(0x130);
inline constexpr uint32_t kNegRoughness = u(0x131);
inline constexpr uint32_t kSpacing = u(0x132);
inline constexpr uint32_t kDensity = u(0x133);
// Wall and barrier.
inline constexpr uint32_t kHardness = u(0x140);
inline constexpr uint32_t kWallSense = u(0x141);
inline constexpr uint32_t kWallOffset = u(0x142);
inline constexpr uint32_t kAngle = u(0x143);
inline constexpr uint32_t kSurfaceFriction = u(0x144);
inline constexpr uint32_t kSurfaceTexture = u(0x145);
inline constexpr uint32_t kClipping = u(0x146);
inline constexpr uint32_t kPosHardness = u(0x147);
inline constexpr uint32_t kNegHardness = u(0x148);
inline constexpr uint32_t kThickness = u(0x149);
// Sweep.
inline constexpr uint32_t kSweepStartAngle = u(0x150);
inline constexpr uint32_t kSweepEndAngle = u(0x151);
inline constexpr uint32_t kSweepSense = u(0x152);
// The named dynamics (§8.4), in DynamicBlock's order.
inline constexpr uint32_t kBlastDirection = u(0x160);
inline constexpr uint32_t kBlastIntensity = u(0x161);
inline constexpr uint32_t kBlastResonance = u(0x162);
inline constexpr uint32_t kBlastDecay = u(0x163);
inline constexpr uint32_t kDynamicMass = u(0x164);
inline constexpr uint32_t kImpactDirection = u(0x165);
inline constexpr uint32_t kImpactIntensity = u(0x166);
inline constexpr uint32_t kElasticity = u(0x167);
inline constexpr uint32_t kCollisionAbsorption = u(0x168);
inline constexpr uint32_t kLiquidDensity = u(0x169);
inline constexpr uint32_t kSettle = u(0x16A);
inline constexpr uint32_t kViscosity = u(0x16B);
inline constexpr uint32_t kInertia = u(0x16C);
inline constexpr uint32_t kPlay = u(0x16D);
inline constexpr uint32_t kStiffness = u(0x16E);
inline constexpr uint32_t kDriftResistance = u(0x16F);
inline constexpr uint32_t kBallMass = u(0x170);
inline constexpr uint32_t kStringLength = u(0x171);
inline constexpr uint32_t kStringCompliance = u(0x172);
inline constexpr uint32_t kBallDamping = u(0x173);
inline constexpr uint32_t kInitialVelocity = u(0x174);
inline constexpr uint32_t kInitialVelocityDirection = u(0x175);
inline constexpr uint32_t kPaddleCompliance = u(0x176);
inline constexpr uint32_t kPaddleDamping = u(0x177);
inline constexpr uint32_t kGravity = u(0x178);
inline constexpr uint32_t kInterimReporting = u(0x179);
// The control law (§8.4), in ControlLawBlock's order.
inline constexpr uint32_t kLawMass = u(0x180);
inline constexpr uint32_t kLawKPos = u(0x181);
inline constexpr uint32_t kLawKNeg = u(0x182);
inline constexpr uint32_t kLawB = u(0x183);
inline constexpr uint32_t kLawVelInit = u(0x184);
inline constexpr uint32_t kLawPosInit = u(0x185);
inline constexpr uint32_t kLawHalfCycles = u(0x186);
inline constexpr uint32_t kLawLength = u(0x187);
inline constexpr uint32_t kLawDrag = u(0x188);
inline constexpr uint32_t kLawGravity = u(0x189);
// Reflex, IDF, report rate.
inline constexpr uint32_t kReflexAssign = u(0x190);
inline constexpr uint32_t kIdfPeriodic = u(0x191);
inline constexpr uint32_t kIdfImpulse = u(0x192);
inline constexpr uint32_t kReportRate = u(0x193);
// PID Pool, vendor part.
inline constexpr uint32_t kFreeEffects = u(0x1A0);
inline constexpr uint32_t kSampleMemory = u(0x1A1);
inline constexpr uint32_t kFreeSamples = u(0x1A2);
// Device Info.
inline constexpr uint32_t kDeviceName = u(0x1B0);
inline constexpr uint32_t kDescription = u(0x1B1);
inline constexpr uint32_t kDeviceClass = u(0x1B2);
inline constexpr uint32_t kAxisId = u(0x1B3);
inline constexpr uint32_t kAxisRotary = u(0x1B4);
inline constexpr uint32_t kHalfTravel = u(0x1B5);
inline constexpr uint32_t kMaxForceMilli = u(0x1B6);
inline constexpr uint32_t kSensorCounts = u(0x1B7);
inline constexpr uint32_t kButtonCount = u(0x1B8);
inline constexpr uint32_t kHatCount = u(0x1B9);
inline constexpr uint32_t kDeadManSwitch = u(0x1BA);
inline constexpr uint32_t kMaxForce = u(0x1BB);
inline constexpr uint32_t kSupportedTypes = u(0x1BC);
inline constexpr uint32_t kEffectSlots = u(0x1BD);
inline constexpr uint32_t kPoolBytes = u(0x1BE);
inline constexpr uint32_t kLocalReflexes = u(0x1BF);
inline constexpr uint32_t kInterimReports = u(0x1C0);
inline constexpr uint32_t kLoopRate = u(0x1C1);
inline constexpr uint32_t kMaxLoopRate = u(0x1C2);
inline constexpr uint32_t kInterimReportRate = u(0x1C3);
inline constexpr uint32_t kFirmwareVersion = u(0x1C4);
inline constexpr uint32_t kVendorRevision = u(0x1C5);
// Command Status.
inline constexpr uint32_t kCommand = u(0x1D0);
inline constexpr uint32_t kErrorCode = u(0x1D1);
inline constexpr uint32_t kErrorText = u(0x1D2);  // Command Error Text's part
inline constexpr uint32_t kErrorValue = u(0x1D3);
inline constexpr uint32_t kAllowedMin = u(0x1D4);
inline constexpr uint32_t kAllowedMax = u(0x1D5);
inline constexpr uint32_t kHasRange = u(0x1D6);
inline constexpr uint32_t kEffectState = u(0x1D8);
inline constexpr uint32_t kCompletedIterations = u(0x1D9);
inline constexpr uint32_t kElapsed = u(0x1DA);
inline constexpr uint32_t kLastEnd = u(0x1DB);
inline constexpr uint32_t kErrorTextPart = u(0x1DC);
// Device Status.
inline constexpr uint32_t kDeviceTime = u(0x1E0);
inline constexpr uint32_t kReportNumber = u(0x1E1);
inline constexpr uint32_t kMotorForce = u(0x1E2);
inline constexpr uint32_t kHandleVelocity = u(0x1E3);
inline constexpr uint32_t kSafetyFade = u(0x1E4);
inline constexpr uint32_t kSafetyFlags = u(0x1E5);
inline constexpr uint32_t kPlayingEffects = u(0x1E6);
inline constexpr uint32_t kResidentEffects = u(0x1E7);
inline constexpr uint32_t kOverruns = u(0x1E8);
inline constexpr uint32_t kMeasuredRate = u(0x1E9);
inline constexpr uint32_t kDroppedReports = u(0x1EA);
inline constexpr uint32_t kPage = u(0x1EB);
inline constexpr uint32_t kPages = u(0x1EC);
inline constexpr uint32_t kEffectCount = u(0x1ED);
// Dynamic Report.
inline constexpr uint32_t kFinalReport = u(0x1F0);
inline constexpr uint32_t kMassPosition = u(0x1F1);
inline constexpr uint32_t kMassVelocity = u(0x1F2);
inline constexpr uint32_t kFirstAxis = u(0x1F3);
}  // namespace vendor

}  // namespace feel::protocol::usage

namespace feel::protocol::usage {

// The usage of each feel EffectType, in the enum's order: PID's ET usage where PID 1.0 has
// the type, a vendor usage otherwise. Set Effect's and Create New Effect's Effect Type is
// a PID named array over this list, so value v (the EffectType) selects entry v.
inline constexpr uint32_t kEffectTypeUsages[kEffectTypeCount] = {
    pid::kEtSpring, pid::kEtDamper, pid::kEtInertia, pid::kEtFriction,
    vendor::effect_type(4),   // angle_spring
    vendor::effect_type(5),   // axis_barrier
    vendor::effect_type(6),   // angle_barrier
    vendor::effect_type(7),   // axis_wall
    vendor::effect_type(8),   // angle_wall
    vendor::effect_type(9),   // texture
    vendor::effect_type(10),  // vector_force
    pid::kEtConstantForce,
    vendor::effect_type(12),  // smart_pop
    pid::kEtSine, pid::kEtSquare, pid::kEtTriangle, pid::kEtSawtoothUp, pid::kEtSawtoothDown,
    vendor::effect_type(18),  // sweep_sine
    vendor::effect_type(19),  // sweep_square
    vendor::effect_type(20),  // sweep_triangle
    vendor::effect_type(21),  // sweep_saw_up
    vendor::effect_type(22),  // sweep_saw_down
    pid::kEtCustomForceData,  // force_profile
    pid::kEtRamp,
    vendor::effect_type(25),  // dynamic_recoil
    vendor::effect_type(26),  // dynamic_impact
    vendor::effect_type(27),  // dynamic_liquid
    vendor::effect_type(28),  // dynamic_inertia
    vendor::effect_type(29),  // dynamic_center_drift
    vendor::effect_type(30),  // dynamic_control_law
    vendor::effect_type(31),  // dynamic_sling
    vendor::effect_type(32),  // dynamic_paddle
};
static_assert(static_cast<int>(EffectType::ramp) == 24 && static_cast<int>(EffectType::constant) == 11,
              "kEffectTypeUsages follows EffectType's order");

// Set Effect's Direction collection: two angles, Ordinal 1 (the polar angle, or the
// spherical azimuth) and Ordinal 2 (the spherical elevation).
inline constexpr uint32_t kDirectionOrdinals[2] = {ordinal(1), ordinal(2)};

// The six axes in feel's order (axis.hpp): Generic Desktop X, Y, Z, Rx, Ry, Rz.
inline constexpr uint32_t kAxisUsages[6] = {gd::kX, gd::kY, gd::kZ, gd::kRx, gd::kRy, gd::kRz};

}  // namespace feel::protocol::usage
