#include "update_cost_meter.h"

#include <cstdio>
#include <ctime>

namespace dressed_human {
namespace {

constexpr int kFramesPerMean = 30;

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

void UpdateCostMeter::start() { started_ = threadCpuSeconds(); }

std::string UpdateCostMeter::stop() {
  cpu_seconds_ += threadCpuSeconds() - started_;
  if (++frames_ < kFramesPerMean) return {};
  char text[64];
  std::snprintf(text, sizeof(text), "%.3f ms CPU per frame", 1e3 * cpu_seconds_ / frames_);
  cpu_seconds_ = 0.0;
  frames_ = 0;
  return text;
}

}  // namespace dressed_human
