// main() for ossa-bench: runs every benchmark, then prints, for each benchmark named
// "<group>:ossa<args>" with a partner "<group>:reference<args>", the ratio of their CPU times
// (of their wall-clock times for benchmarks registered with UseRealTime, "/real_time" in the
// name: the multi-threaded herds, whose work is done on other threads than the timed one).
// A ratio below 1 means ossa is faster than the reference. A reference that does not do the
// same work as its contender says what it does instead in its label (state.SetLabel), and the
// table prints that label after the ratio.
//
// With --benchmark_repetitions=N the table uses each benchmark's median over the repetitions
// (Google Benchmark's "_median" aggregate row), so it works with
// --benchmark_report_aggregates_only=true too; without repetitions, the single run.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

// CPU time per iteration, ns, of one benchmark: the median aggregate when there is one, else
// the mean aggregate, else the mean of the per-repetition rows.
struct Timing {
  double median_ns = -1.0;
  double mean_ns = -1.0;
  double run_sum_ns = 0.0;
  int runs = 0;
  std::string label;  // the benchmark's report label (a reference: what it does differently)

  bool known() const { return median_ns >= 0.0 || mean_ns >= 0.0 || runs > 0; }
  double cpu_ns() const { return median_ns >= 0.0 ? median_ns : mean_ns >= 0.0 ? mean_ns : run_sum_ns / runs; }
  const char* source() const { return median_ns >= 0.0 ? "median" : mean_ns >= 0.0 ? "mean" : runs > 1 ? "mean" : "run"; }
};

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const bool aggregate = r.run_type == Run::RT_Aggregate;
      if (aggregate && (r.aggregate_unit != benchmark::kTime ||
                        (r.aggregate_name != "median" && r.aggregate_name != "mean"))) {
        continue;  // stddev, cv, user statistics
      }
      // run_name: the name without the "_median" / "_mean" suffix of aggregate rows.
      const std::string name = r.run_name.str();
      const size_t colon = name.find(':');
      if (colon == std::string::npos) continue;
      const size_t variant_end = name.find('/', colon);
      const std::string variant = name.substr(colon + 1, variant_end == std::string::npos
                                                             ? std::string::npos
                                                             : variant_end - colon - 1);
      const std::string key = name.substr(0, colon) +
                              (variant_end == std::string::npos ? "" : name.substr(variant_end));
      const bool real_time = r.run_name.time_type == "real_time";
      const double ns = (real_time ? r.GetAdjustedRealTime() : r.GetAdjustedCPUTime()) *
                        (r.time_unit == benchmark::kNanosecond    ? 1.0
                         : r.time_unit == benchmark::kMicrosecond ? 1e3
                         : r.time_unit == benchmark::kMillisecond ? 1e6
                                                                  : 1e9);
      Timing& t = timings_[key][variant];
      if (!r.report_label.empty()) t.label = r.report_label;
      if (!aggregate) {
        t.run_sum_ns += ns;
        ++t.runs;
      } else if (r.aggregate_name == "median") {
        t.median_ns = ns;
      } else {
        t.mean_ns = ns;
      }
      if (std::find(order_.begin(), order_.end(), key) == order_.end()) order_.push_back(key);
    }
  }

  void PrintRatios() const {
    std::printf("\n%-48s %14s %14s %9s  %-6s  %s\n", "benchmark", "ossa", "reference", "ratio", "of",
                "the reference, where it does other work");
    for (const std::string& key : order_) {
      const auto& variants = timings_.at(key);
      auto ours = variants.find("ossa");
      auto ref = variants.find("reference");
      if (ours == variants.end() || ref == variants.end() || !ours->second.known() || !ref->second.known()) continue;
      std::printf("%-48s %11.1f ns %11.1f ns %9.3f  %-6s  %s\n", key.c_str(), ours->second.cpu_ns(),
                  ref->second.cpu_ns(), ours->second.cpu_ns() / ref->second.cpu_ns(), ours->second.source(),
                  ref->second.label.c_str());
    }
  }

 private:
  std::map<std::string, std::map<std::string, Timing>> timings_;
  std::vector<std::string> order_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios();
  benchmark::Shutdown();
  return 0;
}
