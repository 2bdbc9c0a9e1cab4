// Binds a validated parameter struct as a small Python value type: keyword-only constructor, validated
// properties, __repr__, __eq__, to_dict(), replace(**changes) and pickling. Logic stays in the C++ struct's
// validate(); this header only translates.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

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
  }

  template <class T>
  ParamClass& field(const char* fname, T P::*member, const char* doc) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, bool>, "fields are double or bool");
    const std::string owner = fields_->type_name;
    const std::string key = fname;
    Field f;
    f.get = [member](const P& p) -> py::object { return py::cast(p.*member); };
    f.repr = [member](const P& p) -> std::string {
      if constexpr (std::is_same_v<T, bool>) {
        return p.*member ? "True" : "False";
      } else {
        return format_value(p.*member);
      }
    };
    f.set = [member, owner, key](P& p, py::handle value) {
      if constexpr (std::is_same_v<T, bool>) {
        if (py::isinstance<py::bool_>(value)) {
          p.*member = value.cast<bool>();
          return;
        }
        const double v = to_double(owner, key, value);
        if (v != 0.0 && v != 1.0) throw_invalid(owner.c_str(), key.c_str(), v, "must be 0/False or 1/True");
        p.*member = (v == 1.0);
      } else {
        p.*member = to_double(owner, key, value);
      }
    };
    fields_->order.push_back(key);
    fields_->by_name[key] = f;
    cls_.def_property(
        fname, [member](const P& p) { return p.*member; },
        [f](P& self, py::handle value) {
          P copy = self;
          f.set(copy, value);
          copy.validate();
          self = copy;
        },
        doc);
    return *this;
  }

  // Defines __init__ and the value-type protocol; call once, after the fields.
  py::class_<P>& finish() {
    auto fields = fields_;
    cls_.def(py::init([fields](const py::kwargs& kw) {
      P p;
      apply(*fields, p, kw);
      p.validate();
      return p;
    }));
    cls_.def("to_dict", [fields](const P& p) { return to_dict(*fields, p); },
             "The parameters as a dict of plain Python values.");
    cls_.def("replace", [fields](const P& p, const py::kwargs& kw) {
      P copy = p;
      apply(*fields, copy, kw);
      copy.validate();
      return copy;
    }, "A validated copy with the given fields changed.");
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
    return cls_;
  }

 private:
  struct Field {
    std::function<py::object(const P&)> get;
    std::function<std::string(const P&)> repr;
    std::function<void(P&, py::handle)> set;
  };
  struct Fields {
    std::string type_name;
    std::vector<std::string> order;
    std::map<std::string, Field> by_name;
  };

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
