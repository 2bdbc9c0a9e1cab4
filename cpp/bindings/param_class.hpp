// Binds a validated parameter struct as a small Python value type: keyword-only constructor, validated
// properties, __repr__, __eq__, to_dict(), replace(**changes) and pickling. Logic stays in the C++ struct's
// validate(); this header only translates.
//
// The constructor and replace() show every field as an explicit keyword argument, typed, with its default (the
// C++ struct's default member initialisers, which are the manual's defaults): the signatures are written from the
// same .field() list that binds the properties, so help(), IPython completion (kp=, kd=...) and the generated
// .pyi stubs see them, and nothing is retyped per class (decision Y2).
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "servobench/common/validate.hpp"

namespace servobench::bindings {

namespace py = pybind11;

template <class P>
class ParamClass {
 public:
  ParamClass(py::module_& m, const char* name, const char* doc)
      : cls_(m, name, doc), fields_(std::make_shared<Fields>()) {
    fields_->type_name = name;
    fields_->qualified_name = py::str(m.attr("__name__")).cast<std::string>() + "." + name;
  }

  template <class T>
  ParamClass& field(const char* fname, T P::*member, const char* doc) {
    return field(fname, member, "", doc);
  }

  // A whole-number field with its range: a value that is not whole or outside gets the range in its message.
  ParamClass& field(const char* fname, int P::*member, const char* doc, WholeRange range) {
    return add<int>(fname, [member](P& p) -> int& { return p.*member; }, "", doc, range);
  }

  // A field with its unit ("" for none): the unit is shown in the docstrings and in FIELD_INFO.
  template <class T>
  ParamClass& field(const char* fname, T P::*member, const char* unit, const char* doc) {
    return add<T>(fname, [member](P& p) -> T& { return p.*member; }, unit, doc);
  }

  // A field of a nested struct (e.g. SineSweepOptions::loop.feedforward), flat in Python.
  template <class M, class T>
  ParamClass& field(const char* fname, M P::*outer, T M::*inner, const char* unit, const char* doc) {
    return add<T>(fname, [outer, inner](P& p) -> T& { return (p.*outer).*inner; }, unit, doc);
  }

  // Binds every field a struct lists in its static describe(visitor): the struct is then the one place that states
  // each option's name, default, unit and meaning (decision OP3).
  ParamClass& described() {
    P::describe([this](const char* fname, auto... rest) { this->field(fname, rest...); });
    return *this;
  }

 private:
  template <class T, class Ref>
  ParamClass& add(const char* fname, Ref ref, const char* unit, const char* doc,
                  WholeRange range = {-2147483647.0, 2147483647.0, ""}) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, bool> || std::is_same_v<T, int> ||
                      std::is_same_v<T, std::vector<double>>,
                  "fields are double, int, bool or a list of doubles");
    const std::string owner = fields_->type_name;
    const std::string key = fname;
    Field f;
    if constexpr (std::is_same_v<T, bool>) {
      f.type = "bool";
    } else if constexpr (std::is_same_v<T, int>) {
      f.type = "float";  // a whole number, shown as a Python float like every number of a parameter class (Y2)
      f.whole = true;
    } else if constexpr (std::is_same_v<T, double>) {
      f.type = "float";
    } else {
      f.type = "list[float]";
    }
    f.unit = unit;
    f.doc = doc;
    f.get = [ref](const P& p) -> py::object {
      if constexpr (std::is_same_v<T, int>) {
        return py::float_(static_cast<double>(ref(const_cast<P&>(p))));
      } else {
        return py::cast(ref(const_cast<P&>(p)));
      }
    };
    f.repr = [ref](const P& p) -> std::string {
      const T v = ref(const_cast<P&>(p));
      if constexpr (std::is_same_v<T, bool>) {
        return v ? "True" : "False";
      } else if constexpr (std::is_same_v<T, int>) {
        return format_value(static_cast<double>(v));
      } else if constexpr (std::is_same_v<T, double>) {
        return format_value(v);
      } else {
        std::string s = "(";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + format_value(v[i]);
        return s + (v.size() == 1 ? ",)" : ")");
      }
    };
    f.set = [ref, owner, key, range](P& p, py::handle value) {
      if constexpr (std::is_same_v<T, bool>) {
        if (py::isinstance<py::bool_>(value)) {
          ref(p) = value.cast<bool>();
          return;
        }
        const double v = to_double(owner, key, value);
        if (v != 0.0 && v != 1.0) throw_invalid(owner.c_str(), key.c_str(), v, "must be 0/False or 1/True");
        ref(p) = (v == 1.0);
      } else if constexpr (std::is_same_v<T, int>) {
        const double v = to_double(owner, key, value);
        if (*range.source) {
          range.check(owner.c_str(), key.c_str(), v);
        } else if (!(std::isfinite(v) && v == std::floor(v) && std::fabs(v) <= 2147483647.0)) {
          throw_invalid(owner.c_str(), key.c_str(), v, "must be a whole number");
        }
        ref(p) = static_cast<int>(v);
      } else if constexpr (std::is_same_v<T, double>) {
        ref(p) = to_double(owner, key, value);
      } else {
        if (!py::isinstance<py::iterable>(value) || py::isinstance<py::str>(value))
          throw py::type_error(owner + "." + key + " must be a sequence of numbers, got " +
                               py::str(py::type::of(value)).cast<std::string>());
        std::vector<double> out;
        for (py::handle item : py::reinterpret_borrow<py::iterable>(value)) out.push_back(to_double(owner, key, item));
        ref(p) = out;
      }
    };
    fields_->order.push_back(key);
    fields_->by_name[key] = f;
    const std::string prop_doc = (f.unit.empty() ? "" : "[" + f.unit + "] ") + f.doc;
    cls_.def_property(
        fname,
        [ref](const P& p) {
          if constexpr (std::is_same_v<T, int>) {
            return static_cast<double>(ref(const_cast<P&>(p)));
          } else {
            return ref(const_cast<P&>(p));
          }
        },
        [f](P& self, py::handle value) {
          P copy = self;
          f.set(copy, value);
          copy.validate();
          self = copy;
        },
        prop_doc.c_str());
    return *this;
  }

 public:
  // Defines __init__ and the value-type protocol; call once, after the fields.
  py::class_<P>& finish() {
    auto fields = fields_;
    {
      // The docstrings carry the explicit signatures (pybind11's own would read "**kwargs").
      py::options options;
      options.disable_function_signatures();
      const std::string init_doc = "__init__" + signature(*fields, true, "None") + "\n\n" + fields->type_name +
                                   " from keyword arguments; each one omitted keeps the manual's default.\n\n" +
                                   field_docs(*fields);
      cls_.def(py::init([fields](const py::kwargs& kw) {
        P p;
        apply(*fields, p, kw);
        p.validate();
        return p;
      }), init_doc.c_str());
      const std::string replace_doc = "replace" + signature(*fields, false, fields->qualified_name) +
                                      "\n\nA validated copy with the given fields changed (the others kept).";
      cls_.def("replace", [fields](const P& p, const py::kwargs& kw) {
        P copy = p;
        apply(*fields, copy, kw);
        copy.validate();
        return copy;
      }, replace_doc.c_str());
    }
    cls_.def("to_dict", [fields](const P& p) { return to_dict(*fields, p); },
             "The parameters as a dict of plain Python values.");
    cls_.def("__repr__", [fields](const P& p) {
      std::string s = fields->type_name + "(";
      bool first = true;
      for (const auto& name : fields->order) {
        if (!first) s += ", ";
        first = false;
        s += name + "=" + fields->by_name.at(name).repr(p);
      }
      return s + ")";
    });
    cls_.def("__eq__", [fields](const P& a, const py::object& other) {
      if (!py::isinstance<P>(other)) return false;
      return to_dict(*fields, a).equal(to_dict(*fields, other.cast<const P&>()));
    });
    cls_.attr("__hash__") = py::none();
    cls_.def(py::pickle([fields](const P& p) { return to_dict(*fields, p); },
                        [fields](const py::dict& d) {
                          P p;
                          apply(*fields, p, d);
                          p.validate();
                          return p;
                        }));
    std::vector<std::string> names = fields_->order;
    cls_.attr("FIELDS") = py::tuple(py::cast(names));
    // The field table as data (name, type, default, unit, doc): what Python wrappers read their defaults, units and
    // docs from (servobench._options; decision OP3).
    py::list info;
    const P defaults{};
    for (const auto& name : fields_->order) {
      const Field& f = fields_->by_name.at(name);
      info.append(py::dict(py::arg("name") = name, py::arg("type") = f.whole ? std::string("int") : f.type,
                           py::arg("default") = f.get(defaults),
                           py::arg("unit") = f.unit, py::arg("doc") = f.doc));
    }
    cls_.attr("FIELD_INFO") = py::tuple(info);
    return cls_;
  }

 private:
  struct Field {
    std::string type;  // the Python annotation: float, int or bool
    std::string unit;  // "" when the field has none
    bool whole = false;  // an int field: a whole number
    std::string doc;
    std::function<py::object(const P&)> get;
    std::function<std::string(const P&)> repr;
    std::function<void(P&, py::handle)> set;
  };
  struct Fields {
    std::string type_name;
    std::string qualified_name;  // servobench._core.<Name>, for annotations
    std::vector<std::string> order;
    std::map<std::string, Field> by_name;
  };

  // "(self, *, kp: float = 0.0, ...) -> ret"; with_defaults false writes "= ..." (replace(): omitted = unchanged).
  // An infinite default ("no limit") is spelled math.inf, which inspect.signature evaluates (a NaN one: ...).
  static std::string signature(const Fields& fields, bool with_defaults, const std::string& ret) {
    const P defaults{};
    std::string s = "(self, *";
    for (const auto& name : fields.order) {
      const Field& f = fields.by_name.at(name);
      std::string value = "...";
      if (with_defaults) {
        const py::object v = f.get(defaults);
        if (!py::isinstance<py::float_>(v) || std::isfinite(v.cast<double>()))
          value = py::repr(v).cast<std::string>();  // Python's own spelling: 0.0, 32767.0, True
        else if (std::isinf(v.cast<double>()))
          value = v.cast<double>() > 0 ? "math.inf" : "-math.inf";  // inspect.signature evaluates math.inf
      }
      s += ", " + name + ": " + f.type + " = " + value;
    }
    return s + ") -> " + ret;
  }

  static std::string field_docs(const Fields& fields) {
    std::string s = "Parameters:\n";
    for (const auto& name : fields.order) {
      const Field& f = fields.by_name.at(name);
      s += "    " + name + (f.unit.empty() ? "" : " [" + f.unit + "]") + ": " + f.doc + "\n";
    }
    return s;
  }

  static double to_double(const std::string& owner, const std::string& key, py::handle value) {
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
                                             py::hasattr(value, "__float__"))) {
      throw py::type_error(owner + "." + key + " must be a number, got " +
                           py::str(py::type::of(value)).cast<std::string>());
    }
    return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  }

  static void apply(const Fields& fields, P& p, const py::dict& kw) {
    for (const auto& item : kw) {
      const std::string key = py::str(item.first);
      auto it = fields.by_name.find(key);
      if (it == fields.by_name.end()) {
        std::string allowed;
        for (const auto& n : fields.order) allowed += (allowed.empty() ? "" : ", ") + n;
        throw py::type_error(fields.type_name + "() got an unexpected keyword argument '" + key +
                             "'; its fields are: " + allowed);
      }
      it->second.set(p, item.second);
    }
  }

  static py::dict to_dict(const Fields& fields, const P& p) {
    py::dict d;
    for (const auto& name : fields.order) d[py::str(name)] = fields.by_name.at(name).get(p);
    return d;
  }

  py::class_<P> cls_;
  std::shared_ptr<Fields> fields_;
};

}  // namespace servobench::bindings
