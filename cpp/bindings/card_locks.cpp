// The card's lock for the vendor bindings (object_lock.hpp): every _core function whose first parameter is the
// card (`ge_command(card, ...)`, `aps_point_tables(card)`, ...) holds the card's state lock while it runs, and a
// vendor module such a function returns by reference (GeList, ApsPointTables, GtsCard, ...) shares the card's
// locks, so its methods wait for the running chunk of a `Card.run` on another thread exactly like the card's own
// methods (serialise_methods). Without this a dialect call from one thread could change a module's registers in
// the middle of another thread's tick.
//
// Applied once, after every binding file registered its functions (module.cpp): the binding files stay thin and
// a new card function is covered by its signature alone. A function that runs the card itself (takes the run
// lock, like Card.run) must not be a module-level function with `card` first: it would take the state lock
// before the run lock (the order is run, then state) -- such functions are Card methods excluded by name.
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "object_lock.hpp"
#include "servobench/machine/axis.hpp"
#include "servobench/machine/card.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;

namespace {

// The objects sharing each live card's locks (held with the GIL): forgotten when the card's Python object goes.
std::unordered_map<const void*, std::vector<const void*>>& shared_with() {
  static auto* m = new std::unordered_map<const void*, std::vector<const void*>>();
  return *m;
}

// The types whose methods take their object's state lock (wrapped the first time a card returns one).
std::unordered_set<PyObject*>& serialised_types() {
  static auto* s = new std::unordered_set<PyObject*>();
  return *s;
}

std::string doc_of(py::handle f) {
  const py::object d = py::getattr(f, "__doc__", py::none());
  return d.is_none() ? std::string() : py::str(d).cast<std::string>();
}

// Wraps a module type's methods once (serialise_methods, object_lock.hpp: the one wrapper, keyed by the instance).
void serialise_type(py::handle cls) {
  if (serialised_types().insert(cls.ptr()).second) serialise_methods(cls);
}

// A result the card returned by reference (Python does not own it: a module inside the card) shares its locks.
void share_with_card(py::handle result, py::handle card_obj, const Card* card) {
  if (py::detail::get_type_info(Py_TYPE(result.ptr())) == nullptr) return;
  if (py::isinstance<machine::Axis>(result)) return;  // an axis has its own locks (the card's run takes them)
  if (reinterpret_cast<py::detail::instance*>(result.ptr())->owned) return;  // a value of its own
  const void* key = cpp_object(result);
  if (key == nullptr || key == card) return;
  auto& shared = shared_with();
  auto it = shared.find(card);
  if (it == shared.end()) {
    // First module of this card: forget the shared entries when the card's Python object is collected (the
    // modules die with the card, and their addresses may be reused).
    it = shared.emplace(card, std::vector<const void*>{}).first;
    py::cpp_function forget([card](py::handle weakref) {
      auto& s = shared_with();
      auto f = s.find(card);
      if (f != s.end()) {
        for (const void* k : f->second) forget_locks(k);
        s.erase(f);
      }
      weakref.dec_ref();
    });
    (void)py::weakref(card_obj, forget).release();
  }
  auto& keys = it->second;
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
    share_locks(key, card);
    keys.push_back(key);
  }
  serialise_type(py::type::handle_of(result));
}

bool takes_card_first(const std::string& name, py::handle f) {
  const std::string doc = doc_of(f);
  const std::string line = doc.substr(0, doc.find('\n'));
  return line.rfind(name + "(card: ", 0) == 0;
}

}  // namespace

void serialise_card_functions(py::module_& m) {
  std::vector<std::pair<std::string, py::object>> items;
  for (auto item : py::dict(m.attr("__dict__")))
    items.emplace_back(py::str(item.first).cast<std::string>(), py::reinterpret_borrow<py::object>(item.second));
  py::list names;
  for (auto& [name, f] : items) {
    if (!PyCFunction_Check(f.ptr()) || !takes_card_first(name, f)) continue;
    py::options opts;
    opts.disable_function_signatures();
    m.attr(name.c_str()) = py::cpp_function(
        [f = f](py::args args, py::kwargs kw) -> py::object {
          py::handle card_obj;
          if (args.size() > 0 && py::isinstance<Card>(args[0])) card_obj = args[0];
          else if (kw.contains("card") && py::isinstance<Card>(kw["card"])) card_obj = kw["card"];
          if (!card_obj) return f(*args, **kw);  // the wrapped function raises its own TypeError
          const Card* card = &card_obj.cast<const Card&>();
          auto lk = lock_releasing_gil(locks_of(card)->state);
          py::object r = f(*args, **kw);
          share_with_card(r, card_obj, card);
          return r;
        },
        py::name(name.c_str()), py::scope(m), py::doc(doc_of(f).c_str()));
    names.append(name);
  }
  m.attr("_CARD_LOCKED_FUNCTIONS") = py::tuple(names);
  m.def("_shares_card_locks", [](py::handle obj, py::handle card) {
    const void* a = cpp_object(obj);
    const void* b = cpp_object(card);
    return a != nullptr && b != nullptr && locks_of(a) == locks_of(b);
  }, py::arg("obj"), py::arg("card"), "Whether obj's methods take the card's locks (a test hook).");
}

}  // namespace servobench::bindings
