// Card bindings of the GE SX coordinate system (vendor/googol/ge_crd.hpp). Thin: no logic.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>

#include "servobench/machine/card_group.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/googol/ge_crd.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;

void bind_card_ge_path(py::class_<Card>& c) {
  c.def("ge_crd_setup", [](Card& k, const std::vector<double>& offsets, double start_vel, double max_vel,
                           double stop_acc, double fifo_capacity, double dim) {
         vendor::googol::GeCrdSetup s;
         s.offsets = offsets;
         s.start_vel = start_vel;
         s.max_vel = max_vel;
         s.stop_acc = stop_acc;
         s.fifo_capacity = fifo_capacity;
         s.dim = dim;
         vendor::googol::ge_crd_setup(k, s);
       }, py::arg("offsets") = std::vector<double>{}, py::arg("start_vel") = 0.5, py::arg("max_vel") = 256.0,
       py::arg("stop_acc") = 0.0, py::arg("fifo_capacity") = 4096.0, py::arg("dim") = 0.0,
       "(Re)builds the GE SX crd (X..A = axes 1..dim, dim 0 = up to 4; axis = coordinate + offset) at the present profile positions;\n"
       "pulse, pulse/ms, pulse/ms^2. Refused while it or one of its axes moves.")
      .def("ge_crd_exists", [](Card& k) { return vendor::googol::ge_crd_exists(k); })
      .def("ge_path", [](py::object self) {
             Card& k = self.cast<Card&>();
             vendor::googol::ge_path(k);  // refuses when not set up
             std::shared_ptr<machine::CardGroup> g = k.modes().group_shared(vendor::googol::kGeCrdSlot);
             auto* path = &static_cast<machine::PathGroup*>(g.get())->path();
             struct Keep {
               std::shared_ptr<machine::CardGroup> owner;
               py::object card;
             };
             auto* keep = new Keep{g, self};
             py::capsule cap(keep, [](void* p) { delete static_cast<Keep*>(p); });
             return py::cast(path, py::return_value_policy::reference_internal, cap);
           }, "the GE crd's PathGenerator (pulse, ms), hosted in card group slot 4");
}

}  // namespace servobench::bindings
