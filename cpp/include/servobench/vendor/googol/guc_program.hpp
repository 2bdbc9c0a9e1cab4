// GucProgram: the GUC-ECAT motion program's card state (GUC seed 002 Chapter 5, L2100-2560; decisions GS13-GS14,
// GT12, GY1-): a card module (machine/card_hooks.hpp, Card::module<M>()) that owns
//   - the downloaded program's symbol tables (what MCT2008's .ini file holds, L2240-2250): its functions in id
//     order (GT_GetFunId: id 1..), each with its variables (parameters first; TVarInfo.id = the index), and the
//     global variables (TVarInfo.id = the index among them), given by the host's loader after GT_Download;
//   - the 32 threads 0..31 (L2113, L2170-2175): binding (funId, page), run/pause state and the TThreadSts word
//     (run 1 running, 2 paused, 0 stopped or ended; error the last GT call's code; result; line; L2200-2213);
//   - the 32 data pages 0..31 of local variables and the global page -1 (DINT values, L2215-2233);
//   - the argument checks and codes of GT_Bind ... GT_GetVarValue: 0, 1 refused in this state, 7 out of range;
//   - the scheduling: each servo tick the running threads step once, in thread order (L2117-2120, GS14).
// The program's code is the host's: a Python function per motion function, run as a generator, one step per tick
// (GS13). The host asks next_step() which thread steps now (with its start arguments when it has just been
// started) and reports the step's outcome with stepped(); a GT call the step makes reports its code with
// record_error(). Values are doubles holding DINT integers (exact in a double); a local the host reports may be
// a fraction (a Python division), kept as it is.
// Thread safety: no lock of its own; the bindings hold the card's state lock around every call (card_locks.cpp).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// One motion function of the downloaded program.
struct GucFunction {
  std::string name;
  std::vector<std::string> vars;          // its variables, parameters first (TVarInfo.id = index)
  std::vector<bool> param_has_default;    // one per parameter: an unset one without a default starts at 0
  int first_line = 0;                     // the program line of its definition (TThreadSts.line at the start)
};

// TThreadSts (L2200-2213).
struct GucThreadSts {
  int run = 0;          // 1 running, 2 paused, 0 not running (stopped or ended)
  int error = 0;        // the last GT call's code; 1 if the function raised (the thread stops)
  double result = 0.0;  // the function's return value
  int line = 0;         // the program line the thread stands on
};

// A variable named by GT_GetVarId (TVarInfo, L2158-2166): function "" = a global.
struct GucVarInfo {
  int id = -1;
  std::string function;
  std::string name;
};

// What the host does for one thread this tick: start its function (start = true: a new generator from `args`,
// the parameters by name) or step the generator it holds.
struct GucStep {
  int thread = -1;
  bool start = false;
  int fun_id = 0;
  std::vector<std::pair<std::string, double>> args;
};

// How a step ended (GucProgram::stepped).
enum class GucStepEnd : int { Yielded = 0, Returned = 1, Raised = 2 };

class GucProgram final : public machine::CardHooks {
 public:
  static constexpr int kThreads = 32;     // threads 0..31 (L2113, L2170-2175)
  static constexpr int kPages = 32;       // data pages 0..31 (L2173, L2254)
  static constexpr int kGlobalPage = -1;  // the page of the global variables (L2217-2219)
  static constexpr int kMaxCount = 8;     // GT_Set/GetVarValue count 1..8 (L2221, L2231)
  static constexpr double kDintMin = -2147483648.0, kDintMax = 2147483647.0;  // DINT (32-bit int, L3082)

  explicit GucProgram(machine::Card& card);  // the module<M>() constructor; the program needs no axis

  // -- download (GT_Download, L2143-2145, L2243-2245) ----------------------------------------------------------------
  // A new program: every thread stops and is unbound, the pages are cleared, the globals take `values`.
  void load(std::vector<GucFunction> functions, std::vector<std::string> globals, std::vector<double> values);
  bool loaded() const { return loaded_; }
  // Every thread stops (GT_Close, GT_Reset, a new download); bindings and the program stay.
  void stop_all();

  // -- symbols (GT_GetFunId L2150-2152, GT_GetVarId L2158-2166): 1 when there is no such name ------------------------
  std::pair<GucCode, int> fun_id(const std::string& name) const;
  std::pair<GucCode, GucVarInfo> var_id(const std::string& function, const std::string& var) const;

  // -- threads (L2170-2213): thread, page 0..31, funId 1..2^15 else 7 -----------------------------------------------
  // 1 while the thread runs or is paused (L2256), for a function the program does not have, a page another
  // thread is bound to (L2258).
  GucCode bind(double thread, double fun_id, double page);
  // Starts the thread from its function's beginning with its page's locals as arguments, or resumes a paused one;
  // it steps from the next servo tick. 1 if unbound or already running.
  GucCode run_thread(double thread);
  GucCode stop_thread(double thread);    // any state: 0 (a stopped thread starts from the beginning again)
  GucCode pause_thread(double thread);   // 1 if it does not run
  std::pair<GucCode, GucThreadSts> thread_status(double thread) const;
  // True while some thread is started and not ended (paused included): the host steps while this holds.
  bool any_active() const;

  // -- variables (L2215-2233): page -1 globals, 0..31 locals; count 1..8 ----------------------------------------------
  // The variable is TVarInfo's (id, function): id the index among function's variables ("" = the globals).
  // Writes `count` values from `var` on: 7 for a page, count or value (not a DINT integer) out of range or fewer
  // values than count; 1 for a variable that is not on that page or runs past its function's/the globals' last.
  GucCode set_var_value(double page, double id, const std::string& function, const std::vector<double>& values,
                        double count);
  // Reads `count` values: 7 for a page out of range, 1 for a bad count or variable. A page whose thread is active
  // reads the thread's live locals where it has them (else the page's value; a value never set reads 0).
  std::pair<GucCode, std::vector<double>> var_value(double page, double id, const std::string& function,
                                                    double count) const;

  // -- the host's stepping (once per servo tick, after the tick) -------------------------------------------------------
  // The next thread after `after` (-1: the first) to step now: running and not paused, in thread order. It becomes
  // the current thread (record_error applies to it) until stepped().
  std::optional<GucStep> next_step(int after);
  // The outcome of the current thread's step: yielded (still running), returned `value`, raised (error 1, the
  // thread stops); `line` the line it stands on (0: unchanged); `locals` its variables' values now, in the
  // function's variable order (nullopt: not bound yet). Returns next_step(thread): the host's next thread this tick.
  std::optional<GucStep> stepped(int thread, GucStepEnd end, double value, int line,
                                 const std::vector<std::optional<double>>& locals);
  // The code of a GT call the current thread made (TThreadSts.error); ignored outside a step.
  void record_error(int code);
  // The globals as the program's namespace holds them: the host writes them into the namespace before it steps
  // and reads them back after (the program assigns them; GT_SetVarValue(-1, ...) writes them here).
  const std::vector<std::string>& global_names() const { return global_names_; }
  const std::vector<double>& global_values() const { return globals_; }
  void set_global_values(const std::vector<double>& values);  // the same count, else std::invalid_argument

  // -- hooks -------------------------------------------------------------------------------------------------------
  void reset() override;  // GT_Reset: the threads stop; the program stays until power-off (L2245)

 private:
  struct Thread {
    int fun_id = 0;       // 0 unbound
    int page = -1;        // -1 unbound
    bool active = false;  // started and not ended (the host holds its generator)
    bool start = false;   // started, its generator not made yet
    bool paused = false;
    GucThreadSts sts;
    std::vector<std::optional<double>> live;  // its variables as the host last reported them
    std::vector<std::pair<std::string, double>> args;  // the start arguments (taken at GT_RunThread)
  };

  void record_step(int thread, GucStepEnd end, double value, int line,
                   const std::vector<std::optional<double>>& locals);
  Thread* thread_at(double thread);
  const Thread* thread_at(double thread) const;
  // The variable names `count` from id on, on `page`, or nullopt.
  std::optional<std::vector<std::string>> names_of(int page, double id, const std::string& function, int count) const;
  const GucFunction* function_named(const std::string& name) const;

  bool loaded_ = false;
  std::vector<GucFunction> functions_;
  std::vector<std::string> global_names_;
  std::vector<double> globals_;
  std::array<Thread, kThreads> threads_{};
  std::array<std::map<std::string, double>, kPages> pages_{};
  int current_ = -1;
};

// The card's GUC motion-program module (created and attached on first use).
GucProgram& guc_program(machine::Card& card);

}  // namespace servobench::vendor::googol
