// feel's vendor-defined output reports (host -> device): the effect blocks PID 1.0 has no
// report for (textures, walls, barriers, sweeps, Dynamics and their control law) and the
// device settings it lacks (reflexes, IDF, report rate, keep-alive, status requests).
// Their collection and field usages are on the vendor page 0xFF00; a field that means
// what a PID usage means (the Effect Block Index) keeps the PID usage.
//
// Widths: every parameter of effect.hpp fits 16 bits (±10000 signed, 0..35999 unsigned),
// so the wire is narrower than the int32_t members; the range check guarantees nothing is
// lost.
#include "hid_usages.hpp"
#include "report_table.hpp"

namespace feel::protocol::detail {
namespace {

using namespace usage;

constexpr Range kBinary{0, 1};
constexpr Range kReportRateHz{100, 1000};

#define SEQUENCE(R) FEEL_FIELD(R, sequence, u32(vendor::kSequence, kAnyU32))
#define BLOCK(R) FEEL_FIELD(R, block, u16(pid::kEffectBlockIndex, kBlock))

constexpr FieldSpec kSetTexture[] = {
    SEQUENCE(SetTextureReport),
    BLOCK(SetTextureReport),
    FEEL_FIELD(SetTextureReport, texture.pos_roughness, u16(vendor::kPosRoughness, range::kPositiveLevel)),
    FEEL_FIELD(SetTextureReport, texture.neg_roughness, u16(vendor::kNegRoughness, range::kPositiveLevel)),
    FEEL_FIELD(SetTextureReport, texture.spacing, u16(vendor::kSpacing, range::kPositiveLevel)),
    FEEL_FIELD(SetTextureReport, texture.density, u16(vendor::kDensity, range::kPositiveLevel)),
};

constexpr FieldSpec kSetWall[] = {
    SEQUENCE(SetWallReport),
    BLOCK(SetWallReport),
    FEEL_FIELD(SetWallReport, wall.hardness, i16(vendor::kHardness, range::kSignedLevel)),
    FEEL_FIELD(SetWallReport, wall.sense, u8(vendor::kWallSense, kBinary)),
    FEEL_FIELD(SetWallReport, wall.offset, i16(vendor::kWallOffset, range::kSignedLevel)),
    FEEL_FIELD(SetWallReport, wall.offset_mode, u8(vendor::kOffsetMode, kBinary)),
    FEEL_FIELD(SetWallReport, wall.angle, u16(vendor::kAngle, range::kAngle).in(FieldUnit::centidegrees)),
    FEEL_FIELD(SetWallReport, wall.surface_friction, u16(vendor::kSurfaceFriction, range::kLevel)),
    FEEL_FIELD(SetWallReport, wall.surface_texture, u16(vendor::kSurfaceTexture, range::kLevel)),
    FEEL_FIELD(SetWallReport, wall.clipping, flag(vendor::kClipping)),
};

constexpr FieldSpec kSetBarrier[] = {
    SEQUENCE(SetBarrierReport),
    BLOCK(SetBarrierReport),
    FEEL_FIELD(SetBarrierReport, barrier.pos_hardness, i16(vendor::kPosHardness, range::kSignedLevel)),
    FEEL_FIELD(SetBarrierReport, barrier.neg_hardness, i16(vendor::kNegHardness, range::kSignedLevel)),
    FEEL_FIELD(SetBarrierReport, barrier.thickness, u16(vendor::kThickness, range::kPositiveLevel)),
    FEEL_FIELD(SetBarrierReport, barrier.offset, i16(vendor::kWallOffset, range::kSignedLevel)),
    FEEL_FIELD(SetBarrierReport, barrier.offset_mode, u8(vendor::kOffsetMode, kBinary)),
    FEEL_FIELD(SetBarrierReport, barrier.angle,
               u16(vendor::kAngle, range::kAngle).in(FieldUnit::centidegrees)),
    FEEL_FIELD(SetBarrierReport, barrier.surface_friction, u16(vendor::kSurfaceFriction, range::kLevel)),
    FEEL_FIELD(SetBarrierReport, barrier.surface_texture, u16(vendor::kSurfaceTexture, range::kLevel)),
};

constexpr FieldSpec kSetSweep[] = {
    SEQUENCE(SetSweepReport),
    BLOCK(SetSweepReport),
    FEEL_FIELD(SetSweepReport, start_angle,
               u16(vendor::kSweepStartAngle, range::kAngle).in(FieldUnit::centidegrees)),
    FEEL_FIELD(SetSweepReport, end_angle,
               u16(vendor::kSweepEndAngle, range::kAngle).in(FieldUnit::centidegrees)),
    FEEL_FIELD(SetSweepReport, sense, u8(vendor::kSweepSense, kBinary)),
};

// DynamicBlock's fields in its order; control_law travels in Set Control Law.
#define DYN(member, usage_id, r) FEEL_FIELD(SetDynamicReport, dynamic.member, u16(usage_id, r))
#define DYN_ANGLE(member, usage_id) \
    FEEL_FIELD(SetDynamicReport, dynamic.member, u16(usage_id, range::kAngle).in(FieldUnit::centidegrees))
constexpr FieldSpec kSetDynamic[] = {
    SEQUENCE(SetDynamicReport),
    BLOCK(SetDynamicReport),
    DYN_ANGLE(blast_direction, vendor::kBlastDirection),
    DYN(blast_intensity, vendor::kBlastIntensity, range::kSignedLevel),
    DYN(blast_resonance, vendor::kBlastResonance, range::kPositiveLevel),
    DYN(blast_decay, vendor::kBlastDecay, range::kLevel),
    DYN(dynamic_mass, vendor::kDynamicMass, range::kDynamicMass),
    DYN_ANGLE(impact_direction, vendor::kImpactDirection),
    DYN(impact_intensity, vendor::kImpactIntensity, range::kSignedLevel),
    DYN(elasticity, vendor::kElasticity, range::kPositiveLevel),
    DYN(collision_absorption, vendor::kCollisionAbsorption, range::kLevel),
    DYN(density, vendor::kLiquidDensity, range::kPositiveLevel),
    DYN(settle, vendor::kSettle, range::kPositiveLevel),
    DYN(viscosity, vendor::kViscosity, range::kLevel),
    DYN(inertia, vendor::kInertia, range::kPositiveLevel),
    DYN(play, vendor::kPlay, range::kLevel),
    DYN(stiffness, vendor::kStiffness, range::kDynamicStiffness),
    DYN(drift_resistance, vendor::kDriftResistance, range::kLevel),
    DYN(ball_mass, vendor::kBallMass, range::kDynamicMass),
    DYN(string_length, vendor::kStringLength, range::kLevel),
    DYN(string_compliance, vendor::kStringCompliance, range::kPositiveLevel),
    DYN(ball_damping, vendor::kBallDamping, range::kLevel),
    DYN(initial_velocity, vendor::kInitialVelocity, range::kSignedLevel),
    DYN_ANGLE(initial_velocity_direction, vendor::kInitialVelocityDirection),
    DYN(paddle_compliance, vendor::kPaddleCompliance, range::kPositiveLevel),
    DYN(paddle_damping, vendor::kPaddleDamping, range::kLevel),
    DYN(gravity, vendor::kGravity, range::kSignedLevel),
    FEEL_FIELD(SetDynamicReport, dynamic.interim_reporting, flag(vendor::kInterimReporting)),
};
#undef DYN
#undef DYN_ANGLE

#define LAW(member, usage_id, r) FEEL_FIELD(SetControlLawReport, law.member, u16(usage_id, r))
constexpr FieldSpec kSetControlLaw[] = {
    SEQUENCE(SetControlLawReport),
    BLOCK(SetControlLawReport),
    FEEL_FIELD(SetControlLawReport, axis_index, u8(pid::kParameterBlockOffset, kAxisIndex)),
    LAW(mass, vendor::kLawMass, range::kDynamicMass),
    LAW(k_pos, vendor::kLawKPos, range::kDynamicStiffness),
    LAW(k_neg, vendor::kLawKNeg, range::kDynamicStiffness),
    LAW(b, vendor::kLawB, range::kLevel),
    LAW(vel_init, vendor::kLawVelInit, range::kSignedLevel),
    LAW(pos_init, vendor::kLawPosInit, range::kSignedLevel),
    LAW(half_cycles, vendor::kLawHalfCycles, range::kHalfCycles),
    LAW(length, vendor::kLawLength, range::kLevel),
    LAW(drag, vendor::kLawDrag, range::kLevel),
    LAW(gravity, vendor::kLawGravity, range::kSignedLevel),
};
#undef LAW

constexpr FieldSpec kReflex[] = {
    SEQUENCE(ReflexReport),
    BLOCK(ReflexReport),
    FEEL_FIELD(ReflexReport, assign, flag(vendor::kReflexAssign)),
};

constexpr FieldSpec kIdfSettings[] = {
    SEQUENCE(IdfSettingsReport),
    FEEL_FIELD(IdfSettingsReport, settings.periodic, flag(vendor::kIdfPeriodic)),
    FEEL_FIELD(IdfSettingsReport, settings.impulse, flag(vendor::kIdfImpulse)),
};

constexpr FieldSpec kReportRate[] = {
    SEQUENCE(ReportRateReport),
    FEEL_FIELD(ReportRateReport, rate_hz, u16(vendor::kReportRate, kReportRateHz).in(FieldUnit::hertz)),
};

constexpr FieldSpec kKeepAlive[] = {
    SEQUENCE(KeepAliveReport),
};

constexpr FieldSpec kEffectStatusRequest[] = {
    SEQUENCE(EffectStatusRequestReport),
    BLOCK(EffectStatusRequestReport),
};

#undef SEQUENCE
#undef BLOCK

constexpr ReportKind kVendorOut = ReportKind::output;

constexpr ReportSpec kVendorReports[] = {
    report<SetTextureReport>(ReportId::set_texture, kVendorOut, "Set Texture", "set_texture",
                             vendor::kSetTextureReport, kSetTexture),
    report<SetWallReport>(ReportId::set_wall, kVendorOut, "Set Wall", "set_wall",
                          vendor::kSetWallReport, kSetWall),
    report<SetBarrierReport>(ReportId::set_barrier, kVendorOut, "Set Barrier", "set_barrier",
                             vendor::kSetBarrierReport, kSetBarrier),
    report<SetSweepReport>(ReportId::set_sweep, kVendorOut, "Set Sweep", "set_sweep",
                           vendor::kSetSweepReport, kSetSweep),
    report<SetDynamicReport>(ReportId::set_dynamic, kVendorOut, "Set Dynamic", "set_dynamic",
                             vendor::kSetDynamicReport, kSetDynamic),
    report<SetControlLawReport>(ReportId::set_control_law, kVendorOut, "Set Control Law",
                                "set_control_law", vendor::kSetControlLawReport, kSetControlLaw),
    report<ReflexReport>(ReportId::reflex, kVendorOut, "Reflex", "reflex", vendor::kReflexReport,
                         kReflex),
    report<IdfSettingsReport>(ReportId::idf_settings, kVendorOut, "IDF Settings", "idf_settings",
                              vendor::kIdfSettingsReport, kIdfSettings),
    report<ReportRateReport>(ReportId::report_rate, kVendorOut, "Report Rate", "report_rate",
                             vendor::kReportRateReport, kReportRate),
    report<KeepAliveReport>(ReportId::keep_alive, kVendorOut, "Keep Alive", "keep_alive",
                            vendor::kKeepAliveReport, kKeepAlive),
    report<EffectStatusRequestReport>(ReportId::effect_status_request, kVendorOut,
                                      "Effect Status Request", "effect_status_request",
                                      vendor::kEffectStatusRequestReport, kEffectStatusRequest),
};

}  // namespace

std::span<const ReportSpec> vendor_output_reports() noexcept { return kVendorReports; }

}  // namespace feel::protocol::detail
