// The APS runner (aps_commands.hpp): one map from the manual's name to its chapter's function, built once from the
// chapters' rows (aps_commands_motion.cpp, aps_commands_interp.cpp,
// aps_commands_compare.cpp). Decision AY1.
#include "servobench/vendor/adlink/aps_commands.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "aps_commands_detail.hpp"

namespace servobench::vendor::adlink {

namespace {

const std::unordered_map<std::string, detail::Entry>& commands() {
  static const auto kMap = [] {
    std::unordered_map<std::string, detail::Entry> m;
    for (const auto* rows : {&detail::motion_commands(), &detail::interp_commands(), &detail::compare_commands()})
      for (const detail::Named& r : *rows) m.emplace(r.name, r.entry);
    return m;
  }();
  return kMap;
}

}  // namespace

ApsReply aps_command(machine::Card* card, const std::string& name, const ApsArgs& args) {
  const auto it = commands().find(name);
  if (it == commands().end()) throw std::invalid_argument("aps_command: name = '" + name + "' is no APS function");
  const detail::Entry& e = it->second;
  ApsArgs padded = args;  // the arguments a call left out are not given (None)
  padded.resize(std::max(args.size(), std::string(e.args).size()));
  ApsReply r = e.impl(detail::Call{card, padded});
  r.kinds = e.reply;
  return r;
}

const std::vector<ApsCommandShape>& aps_command_shapes() {
  static const auto kShapes = [] {
    std::vector<ApsCommandShape> out;
    for (const auto* rows : {&detail::motion_commands(), &detail::interp_commands(), &detail::compare_commands()})
      for (const detail::Named& r : *rows) out.push_back({r.name, r.entry.args, r.entry.reply});
    return out;
  }();
  return kShapes;
}

}  // namespace servobench::vendor::adlink
