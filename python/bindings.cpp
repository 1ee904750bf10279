// The compiled part of `import kessler` (docs/python.md): decks, runs and the verification problems,
// on the same code as the `kessler` program. The package python/kessler/ wraps it; nothing here is
// meant to be called directly.
#include "app/simulation.hpp"
#include "app/verification.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "io/deck.hpp"
#include "solver/methods.hpp"

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace kessler::python {
namespace {

// Restores the log level when a call ends, however it ends.
class LogLevel {
 public:
  explicit LogLevel(bool quiet) : saved_(log::level()) {
    if (quiet) log::setLevel(log::Level::quiet);
  }
  ~LogLevel() { log::setLevel(saved_); }
  LogLevel(const LogLevel&) = delete;
  LogLevel& operator=(const LogLevel&) = delete;

 private:
  log::Level saved_;
};

// A run with the GIL released. `callback(step, time, end_time, dt)` is called with the GIL held at most
// every `interval` seconds (0: after every step) and after the last step; when it returns False or raises, the run
// stops as an interrupted run does (the state and a checkpoint written), and the exception, if any, is raised here
// after that.
py::tuple run(const io::RunConfig& config, int threads, bool quiet, bool restart, const py::object& callback,
              double interval) {
  app::RunOptions options{.threads = threads, .progress = !quiet && callback.is_none(), .restart = restart};
  options.report_interval = interval;
  std::optional<py::error_already_set> raised;
  if (!callback.is_none()) {
    options.on_progress = [&](const app::ProgressReport& r) {
      py::gil_scoped_acquire gil;
      try {
        const py::object keep = callback(r.step, r.time, r.end_time, r.dt);
        return keep.is_none() || keep.cast<bool>();
      } catch (py::error_already_set& e) {
        raised.emplace(std::move(e));
        return false;
      }
    };
  }
  app::RunOutcome outcome;
  {
    const LogLevel level(quiet);
    py::gil_scoped_release released;
    outcome = app::runSimulation(config, options);
  }
  if (raised) throw std::move(*raised);
  return py::make_tuple(outcome.dir, outcome.exit_code, outcome.stopped_by_caller);
}

py::list verifyProblems(const std::vector<std::string>& names, const std::string& method, const py::object& each) {
  app::useVerifyMethod(method);
  py::list outcomes;
  for (const verify::Check* check : app::selectProblems(names)) {
    std::string text;
    {
      py::gil_scoped_release released;
      text = app::outcomeJson(app::runProblem(*check)).dump();
    }
    outcomes.append(text);
    if (!each.is_none()) each(text);
  }
  return outcomes;
}

}  // namespace
}  // namespace kessler::python

PYBIND11_MODULE(_kessler, m) {
  using namespace kessler;
  m.doc() = "Kessler's compiled core; use the package `kessler` (docs/python.md).";

  // Deck and input problems are ValueErrors, numerical failures RuntimeErrors; both carry the
  // message the command line prints (file, line, key, value).
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  static py::exception<Error> kessler_error(m, "Error", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical_error.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(kessler_error.ptr(), e.what());
    }
  });

  py::class_<io::RunConfig>(m, "Deck", "A checked deck, every default filled in and every value in SI units.")
      .def_property_readonly("title", [](const io::RunConfig& c) { return c.title; })
      .def_property_readonly("source", [](const io::RunConfig& c) { return c.deck_path; })
      .def_property_readonly("method", [](const io::RunConfig& c) { return c.method; })
      .def_property_readonly("end_time", [](const io::RunConfig& c) { return c.solver.end_time; })
      .def_property(
          "output_dir", [](const io::RunConfig& c) { return c.output.dir; },
          [](io::RunConfig& c, const std::filesystem::path& dir) { c.output.dir = dir; })
      .def_property_readonly("bodies",
                             [](const io::RunConfig& c) {
                               std::vector<std::string> names;
                               for (const auto& b : c.bodies) names.push_back(b.name);
                               return names;
                             })
      .def("copy", [](const io::RunConfig& c) { return c; })
      .def("yaml", &io::resolvedDeckText, "The resolved deck as YAML (what deck.resolved.yaml holds).")
      .def("__repr__", [](const io::RunConfig& c) {
        return "<kessler.Deck '" + (c.title.empty() ? c.deck_path : c.title) + "', " + c.method + ">";
      });

  m.def("load_deck", &io::parseDeck, py::arg("path"), py::arg("overrides") = std::vector<std::string>{});
  m.def("parse_deck", &io::parseDeckString, py::arg("text"), py::arg("name"),
        py::arg("overrides") = std::vector<std::string>{});
  m.def("restart_deck", &app::restartConfig, py::arg("run_dir"), py::arg("overrides") = std::vector<std::string>{});
  m.def("restart_keys", &app::restartKeys);
  m.def("run", &python::run, py::arg("deck"), py::arg("threads") = 0, py::arg("quiet") = false,
        py::arg("restart") = false, py::arg("callback") = py::none(), py::arg("interval") = 0.2);
  m.def("methods", &methodNames);
  m.def(
      "program", [] { return std::string(KESSLER_PROGRAM); }, "The kessler program built with this module.");
  m.def("verify_problems", [] {
    std::vector<std::pair<std::string, std::string>> list;
    for (const verify::Check& p : verify::problems()) list.emplace_back(p.name, p.description);
    return list;
  });
  m.def("verify", &python::verifyProblems, py::arg("names"), py::arg("method") = "otm", py::arg("each") = py::none());
}
