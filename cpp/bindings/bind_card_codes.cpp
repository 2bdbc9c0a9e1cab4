// Typed vendor return codes (cpp/include/servobench/vendor/*/return_code.hpp) and the codes carried by the card's
// exceptions as attributes, so a dialect maps a refusal with a table, never by reading the message:
//   PathGeometryError.gt_code   the GT/GE code of an impossible geometry (2, 3, 5; 6 for a mapping)
//   CardCommandRefused.fault    the kernel's CommandFault name (e.g. "change_in_motion"), .axis (0-based, -1 card)
#include <pybind11/pybind11.h>

#include "servobench/machine/card.hpp"
#include "servobench/motion/path_segment.hpp"
#include "servobench/vendor/adlink/return_code.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {
// The Python exception types; set once in bind_card_codes (the translator must be a plain function).
py::handle g_geometry_error;
py::handle g_card_refused;

void raise_with(py::handle type, const char* what, const char* name, py::object value, const char* name2 = nullptr,
                py::object value2 = py::none()) {
  py::object exc = type(what);
  exc.attr(name) = std::move(value);
  if (name2) exc.attr(name2) = std::move(value2);
  PyErr_SetObject(type.ptr(), exc.ptr());
}

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const motion::PathGeometryError& e) {
    raise_with(g_geometry_error, e.what(), "gt_code", py::int_(e.gt_code()));
  } catch (const machine::CardCommandRefused& e) {
    raise_with(g_card_refused, e.what(), "fault", py::str(machine::to_string(e.fault())), "axis", py::int_(e.axis()));
  }
}
}  // namespace

void bind_card_codes(py::module_& m) {
  g_geometry_error = m.attr("PathGeometryError");
  g_card_refused = m.attr("CardCommandRefused");
  g_geometry_error.inc_ref();  // kept for the module's lifetime
  g_card_refused.inc_ref();
  py::register_exception_translator(&translate);

  using namespace vendor::googol;
  py::enum_<GtCode>(m, "GtCode", py::arithmetic(), "GT series return codes (seed 000 Table 2-1 L393-408).")
      .value("SUCCESS", GtCode::Success)
      .value("COMMAND_ERROR", GtCode::CommandError)
      .value("ARC_RADIUS_ERROR", GtCode::ArcRadiusError)
      .value("LINE_LENGTH_ERROR", GtCode::LineLengthError)
      .value("SYN_PARAM_ERROR", GtCode::SynParamError)
      .value("ARC_END_POINT_ERROR", GtCode::ArcEndPointError)
      .value("MAP_AXIS_ERROR", GtCode::MapAxisError)
      .value("PARAMETER_ERROR", GtCode::ParameterError)
      .value("COMM_ERROR", GtCode::CommError);
  py::enum_<GeCode>(m, "GeCode", py::arithmetic(), "GE series return codes (seed 001 Table 2-1 L263-270, Table 2-2 L272-283).")
      .value("SUCCESS", GeCode::Success)
      .value("COMMAND_ERROR", GeCode::CommandError)
      .value("ARC_RADIUS_ERROR", GeCode::ArcRadiusError)
      .value("LINE_LENGTH_ERROR", GeCode::LineLengthError)
      .value("SYN_PARAM_ERROR", GeCode::SynParamError)
      .value("ARC_CHORD_ERROR", GeCode::ArcChordError)
      .value("PARAMETER_ERROR", GeCode::ParameterError)
      .value("PROGRAM_RUNNING", GeCode::ProgramRunning)
      .value("REENTERED", GeCode::Reentered)
      .value("COMM_ERROR", GeCode::CommError);
  py::enum_<GucCode>(m, "GucCode", py::arithmetic(), "GUC-ECAT (seed 002 Tab 2-1 L165-180) and iDEABOX (seed 003 Table 3-1 L333-361) "
                                   "return codes.")
      .value("SUCCESS", GucCode::Success)
      .value("COMMAND_ERROR", GucCode::CommandError)
      .value("LICENSE_ERROR", GucCode::LicenseError)
      .value("PARAMETER_ERROR", GucCode::ParameterError)
      .value("COMM_ERROR", GucCode::CommError)
      .value("OPEN_FAILED", GucCode::OpenFailed)
      .value("NO_RESPONSE", GucCode::NoResponse);
  m.def("gt_geometry_code", [](int c) { return gt_geometry_code(c); }, py::arg("gt_code"),
        "The GT code of a PathGeometryError (its gt_code attribute).");
  m.def("ge_geometry_code", [](int c) { return ge_geometry_code(c); }, py::arg("gt_code"),
        "The GE code of a PathGeometryError: a zero-length line is a duplicate point, 1 (GE L3374).");
  m.def("guc_geometry_code", [](int c) { return guc_geometry_code(c); }, py::arg("gt_code"),
        "The GUC-ECAT/iDEABOX code of a PathGeometryError: 7 (GUC L906).");
  py::enum_<vendor::adlink::AdlinkCode>(m, "AdlinkCode", py::arithmetic(),
                                        "ADLINK APS return codes (ErrorCodeDef.h, seed 004 L2285, L2309; V49).")
      .value("ERR_NoError", vendor::adlink::AdlinkCode::NoError)
      .value("ERR_DeviceNotInitial", vendor::adlink::AdlinkCode::DeviceNotInitial)
      .value("ERR_DeviceAlreadyInitialed", vendor::adlink::AdlinkCode::DeviceAlreadyInitialed)
      .value("ERR_ParametersInvalid", vendor::adlink::AdlinkCode::ParametersInvalid)
      .value("ERR_FunctionNotAvailable", vendor::adlink::AdlinkCode::FunctionNotAvailable)
      .value("ERR_DistantNotEnough", vendor::adlink::AdlinkCode::DistantNotEnough)
      .value("ERR_InterruptNotEnable", vendor::adlink::AdlinkCode::InterruptNotEnable)
      .value("ERR_TimeOut", vendor::adlink::AdlinkCode::TimeOut);
}

}  // namespace servobench::bindings
