// Signatures Python can read: pybind11 writes a function's signature as the first line of its docstring
// ("run(self: servobench._core.Axis, command: numpy.ndarray, *, record: bool = True) -> ..."), which help() and
// pybind11-stubgen read but inspect.signature() (IPython's Shift-Tab and keyword completion) does not. CPython takes
// a builtin's signature from a docstring that starts "name(<plain signature>)\n--\n\n" (__text_signature__). This
// header derives that plain signature (names, kinds, literal defaults; no annotations, which CPython's parser
// rejects) from pybind11's line and prepends it, for every function of the module (add_text_signatures, called
// once at the end of the module's init). No logic of the simulator here; only text.
#pragma once

#include <pybind11/pybind11.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace servobench::bindings {

namespace py = pybind11;

namespace signature_detail {

// Splits "a: X[int, float] = (1, 2), b" at the top-level commas (outside brackets and quotes).
inline std::vector<std::string> split_top_level(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  int depth = 0;
  char quote = 0;
  for (char c : s) {
    if (quote) {
      cur += c;
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '\'' || c == '"') quote = c;
    else if (c == '(' || c == '[' || c == '{' || c == '<') ++depth;
    else if (c == ')' || c == ']' || c == '}' || c == '>') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(cur);
      cur.clear();
      continue;
    }
    cur += c;
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// A default CPython's signature parser accepts (a number, a quoted string, True/False/None, math.inf, which it
// evaluates); anything else
// (an enum's <Mode.X: 1>, an array's repr) becomes "..." so the rest of the signature still shows.
inline std::string literal_or_ellipsis(const std::string& v) {
  if (v == "True" || v == "False" || v == "None" || v == "..." || v == "math.inf" || v == "-math.inf") return v;
  if (v.size() >= 2 && (v.front() == '\'' || v.front() == '"') && v.back() == v.front()) return v;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (!v.empty() && end == v.c_str() + v.size() && d == d && d - d == 0.0) return v;  // finite number
  return "...";
}

}  // namespace signature_detail

// "(self: X, a: float, *, b: bool = True) -> Y" -> "(self, /, a, *, b=True)"; "" when it cannot be done.
// `self` is written plainly (not "$self"): pybind11 functions carry a capsule as __self__, which would make
// CPython drop a "$self" parameter twice on bound methods.
inline std::string plain_signature(const std::string& annotated) {
  using namespace signature_detail;
  if (annotated.empty() || annotated.front() != '(') return "";
  int depth = 0;
  std::size_t close = std::string::npos;
  for (std::size_t i = 0; i < annotated.size(); ++i) {
    if (annotated[i] == '(' || annotated[i] == '[') ++depth;
    else if (annotated[i] == ')' || annotated[i] == ']') {
      if (--depth == 0) {
        close = i;
        break;
      }
    }
  }
  if (close == std::string::npos) return "";
  std::vector<std::string> names, defaults;
  bool has_slash = false;
  for (const std::string& raw : split_top_level(annotated.substr(1, close - 1))) {
    const std::string p = trim(raw);
    if (p.empty()) continue;
    std::string name = p, def;
    const auto eq = p.find(" = ");
    if (eq != std::string::npos) {
      name = p.substr(0, eq);
      def = literal_or_ellipsis(trim(p.substr(eq + 3)));
    }
    const auto colon = name.find(':');
    if (colon != std::string::npos) name = trim(name.substr(0, colon));
    if (name == "/") has_slash = true;
    names.push_back(name);
    defaults.push_back(def);
  }
  std::string out = "(";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ", ";
    out += names[i];
    if (!defaults[i].empty()) out += "=" + defaults[i];
    if (i == 0 && names[i] == "self" && !has_slash) out += ", /";  // a builtin's self is positional-only
  }
  out += ")";
  return out;
}

// Prepends "name(<plain signature>)\n--\n\n" to the docstring of one pybind11 function (a builtin), when its
// docstring starts with a single signature (not "Overloaded function.") and has none yet.
inline void add_text_signature(py::handle fn) {
  if (!fn || !PyCFunction_Check(fn.ptr())) return;
  auto* f = reinterpret_cast<PyCFunctionObject*>(fn.ptr());
  PyMethodDef* def = f->m_ml;
  if (def == nullptr || def->ml_doc == nullptr || def->ml_name == nullptr) return;
  const std::string doc = def->ml_doc;
  const std::string name = def->ml_name;
  if (doc.rfind(name + "(", 0) != 0) return;
  if (doc.find("\n--\n\n") != std::string::npos) return;
  if (doc.find("Overloaded function.") != std::string::npos) return;
  const auto eol = doc.find('\n');
  const std::string plain = plain_signature(doc.substr(name.size(), eol == std::string::npos ? std::string::npos
                                                                                              : eol - name.size()));
  if (plain.empty()) return;
  const std::string text = name + plain + "\n--\n\n" + doc;
  std::free(const_cast<char*>(def->ml_doc));  // pybind11 allocates it with strdup and frees it with free
  def->ml_doc = strdup(text.c_str());
}

// Adds text signatures to every function of `scope` (a module or a class): module functions, methods, static
// methods and the accessors of properties, recursing into the classes defined in module `module_name`.
inline void add_text_signatures(py::handle scope, const std::string& module_name, int depth = 0) {
  if (depth > 4) return;
  const py::object property = py::module_::import("builtins").attr("property");
  const py::dict d = scope.attr("__dict__");
  for (auto item : d) {
    py::handle v = item.second;
    if (PyCFunction_Check(v.ptr())) {
      add_text_signature(v);
    } else if (PyInstanceMethod_Check(v.ptr())) {
      add_text_signature(PyInstanceMethod_GET_FUNCTION(v.ptr()));
    } else if (PyObject_TypeCheck(v.ptr(), &PyStaticMethod_Type)) {
      add_text_signature(v.attr("__func__"));
    } else if (py::isinstance(v, property)) {
      add_text_signature(v.attr("fget"));
      add_text_signature(v.attr("fset"));
    } else if (PyType_Check(v.ptr()) && v.ptr() != scope.ptr() &&
               py::str(py::getattr(v, "__module__", py::str(""))).cast<std::string>() == module_name) {
      add_text_signatures(v, module_name, depth + 1);
    }
  }
}

}  // namespace servobench::bindings
