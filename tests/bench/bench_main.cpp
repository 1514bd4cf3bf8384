// main() for ossa-bench: runs every benchmark, then prints, for each benchmark named
// "<group>:ossa<args>" with a partner "<group>:reference<args>", the ratio of their CPU times.
// A ratio below 1 means ossa is faster than the reference.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

struct Timing {
  double cpu_ns = 0.0;
};

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      const std::string name = r.benchmark_name();
      const size_t colon = name.find(':');
      if (colon == std::string::npos) continue;
      const size_t variant_end = name.find('/', colon);
      const std::string variant = name.substr(colon + 1, variant_end == std::string::npos
                                                             ? std::string::npos
                                                             : variant_end - colon - 1);
      const std::string key = name.substr(0, colon) +
                              (variant_end == std::string::npos ? "" : name.substr(variant_end));
      const double ns = r.GetAdjustedCPUTime() *
                        (r.time_unit == benchmark::kNanosecond    ? 1.0
                         : r.time_unit == benchmark::kMicrosecond ? 1e3
                         : r.time_unit == benchmark::kMillisecond ? 1e6
                                                                  : 1e9);
      timings_[key][variant].cpu_ns = ns;
      if (std::find(order_.begin(), order_.end(), key) == order_.end()) order_.push_back(key);
    }
  }

  void PrintRatios() const {
    std::printf("\n%-48s %14s %14s %9s\n", "benchmark", "ossa", "reference", "ratio");
    for (const std::string& key : order_) {
      const auto& variants = timings_.at(key);
      auto ours = variants.find("ossa");
      auto ref = variants.find("reference");
      if (ours == variants.end() || ref == variants.end()) continue;
      std::printf("%-48s %11.1f ns %11.1f ns %9.3f\n", key.c_str(), ours->second.cpu_ns,
                  ref->second.cpu_ns, ours->second.cpu_ns / ref->second.cpu_ns);
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
