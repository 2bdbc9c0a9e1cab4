// The Googol return codes, one enum class per manual: what a library call returns (short / int). The Googol cards
// share 0 (success), 1 (command error: the card ignored the command; GT_GetCmdSts says why), 7 (parameter error)
// and -1 (communication error); codes 2..6 mean different things on different cards, so each card has its own
// type and a code never crosses from one card's dialect to another's.
//
// The kernel refuses a command with a neutral machine::CommandFault (machine/card.hpp) and a path geometry with a
// motion::PathGeometryError; the mapping to these numbers is per card (gt_code(), guc_code() below, the dialects'
// tables), never parsed out of a message. Sources: seed 000 (GT) Table 2-1 L393-408; seed 001 (GE) Table 2-1
// L263-270, Table 2-2 L272-283; seed 002 (GUC-ECAT) Tab 2-1 L165-180; seed 003 (iDEABOX) Table 3-1 L333-361.
#pragma once

namespace servobench::vendor::googol {

// GT series (GT-400 / GT-800 ...), Table 2-1 L393-408.
enum class GtCode : int {
  Success = 0,            // L393
  CommandError = 1,       // the card ignores the command; the reason in GT_GetCmdSts (L395-398, L415)
  ArcRadiusError = 2,     // wrong arc radius (GT_ArcXY/ArcYZ/ArcZX)
  LineLengthError = 3,    // line length zero, negative or beyond bounds (GT_LnXY/LnXYZ/LnXYZA)
  SynParamError = 4,      // vector velocity/acceleration zero, negative or beyond bounds (GT_SetSynVel/SetSynAcc)
  ArcEndPointError = 5,   // wrong end point or radius of an arc (GT_ArcXYP/ArcYZP/ArcZXP)
  MapAxisError = 6,       // coordinate mapping failed or conflicts with an earlier one (GT_MapAxis)
  ParameterError = 7,     // general parameter error (out of range / unreasonable)
  CommError = -1,         // communication error
};

// GE series, PX Table 2-1 L263-270 and SX Table 2-2 L272-283 (2-5 only for the SX path commands).
enum class GeCode : int {
  Success = 0,
  CommandError = 1,        // read GT_GetCmdSts for the reason; also a duplicate look-ahead point (L3374)
  ArcRadiusError = 2,      // arc radius 0 or chord 0 (full circle excepted)
  LineLengthError = 3,     // line length 0 or overflow
  SynParamError = 4,       // (acceleration/)velocity <= 0 or overflow
  ArcChordError = 5,       // arc chord longer than the diameter
  ParameterError = 7,
  ProgramRunning = 9,      // GT_M30 while the program is not finished (L1795, L5175)
  Reentered = -3,          // command re-entered from another thread (L266)
  CommError = -1,          // driver, board, base-address jumper (L287-295)
};

// GUC-ECAT (Tab 2-1 L165-180) and iDEABOX (Table 3-1 L333-361): the same table.
enum class GucCode : int {
  Success = 0,
  CommandError = 1,     // execution condition not met (state, full FIFO/table, empty table)
  LicenseError = 2,     // feature not licensed (GUC-ECAT only)
  ParameterError = 7,   // parameter out of range; also an ill-defined arc (GUC L906)
  CommError = -1,       // host <-> controller communication failed
  OpenFailed = -6,      // opening the card failed (e.g. GT_Open twice, L176)
  NoResponse = -7,      // controller does not respond
};

// A path-geometry refusal's GT/GE code (motion::PathGeometryError::gt_code(): 2, 3, 5 or 6) on each card.
constexpr GtCode gt_geometry_code(int gt_code) { return static_cast<GtCode>(gt_code); }
// GE: a zero-length line is a duplicate point, "1" (L3374); the arc codes are the GT's.
constexpr GeCode ge_geometry_code(int gt_code) {
  return gt_code == 3 ? GeCode::CommandError : static_cast<GeCode>(gt_code);
}
// GUC-ECAT / iDEABOX: every ill-defined segment is a parameter error (GUC L906).
constexpr GucCode guc_geometry_code(int /*gt_code*/) { return GucCode::ParameterError; }

const char* to_string(GtCode code);
const char* to_string(GeCode code);
const char* to_string(GucCode code);

}  // namespace servobench::vendor::googol
