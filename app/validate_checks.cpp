#include "validate_checks.h"

#include <functional>

#include "compare/judge.h"
#include "core/parallel_tasks.h"
#include "io/image_io.h"

namespace vct::app {

void write_pt_images(RunDir& run, const PtRun& pt) {
  RunDir pd(run.file("pt"));
  // One task per AOV, each its own files: the same bytes for any thread count.
  std::vector<const std::pair<const std::string, Image>*> aovs;
  for (const auto& aov : pt.aovs) aovs.push_back(&aov);
  parallel_tasks(int64_t(aovs.size()), [&](int64_t i) {
    const auto& [name, img] = *aovs[size_t(i)];
    if (name.size() > 4 && name.substr(name.size() - 4) == "_var") write_exr(pd.file(name + ".exr"), img);
    else pd.write_color(name, img);
  });
}

namespace {
constexpr int kConcurrentChecksBelowThreads = 4;

struct Task {
  std::string name;
  std::function<void()> run;
  double ms = 0.0, cpu_ms = -1.0;
};
}  // namespace

CheckResults run_checks(RunDir& run, const Scene& scene, const Settings& s, BackendRun& ref, BackendRun& gl,
                        const PtRun& pt, PhaseTimes& phases, bool keep_ref_frame) {
  CheckResults r;
  // Named before any task starts: the writers then only read the sets the others read.
  if (ref.ok()) {
    r.ref_set = keep_ref_frame ? cmp::stage_set_from_frame(*ref.frame, s.vct)
                               : cmp::stage_set_from_frame(std::move(*ref.frame), s.vct);
    if (!keep_ref_frame) ref.frame->mips = VoxelMips();  // no stage; the cones were traced
    cmp::name_stage_files(run.file("ref"), r.ref_set);
  }
  // The GL frame's voxel grid moves into its set: the judge's passes on GL's own inputs read its
  // mips, shadow maps, G-buffer and images, never the grid (docs/performance.md, "Validate's memory").
  if (gl.ok()) cmp::name_stage_files(run.file("gl"), r.gl_set = cmp::stage_set_taking_voxels(*gl.frame, s.vct));
  std::vector<Task> tasks;
  // The longest chain first (one thread: its inner loops run serially inside a task).
  if (ref.ok() && gl.ok())
    tasks.push_back({"compare gl vs ref (stages, difference images; cones on gl's voxels)", [&] {
                       // The one judge (compare/judge.h): cone and shading stages on GL's own inputs,
                       // so a legitimate voxel tie upstream does not fail a correct marcher downstream.
                       r.report = cmp::judge(r.ref_set, r.gl_set, {&scene, &*gl.frame, &s.vct},
                                             {10, run.file("compare"), "compare/", {}});
                     }});
  if (ref.ok()) tasks.push_back({"write stage set ref", [&] { cmp::write_named_stage_set(r.ref_set); }});
  if (gl.ok()) tasks.push_back({"write stage set gl", [&] { cmp::write_named_stage_set(r.gl_set); }});
  if (pt.ok()) tasks.push_back({"write pt images", [&] { write_pt_images(run, pt); }});
  if (ref.ok() && pt.ok())
    tasks.push_back({"bias ref vs pt", [&] {
                       r.bias_ref = cmp::measure_bias(r.ref_set, pt.aovs, {3.0, run.file("bias"), "bias/"});
                     }});
  if (ref.ok() && gl.ok() && pt.ok())
    tasks.push_back({"bias gl vs pt", [&] {
                       r.bias_gl = cmp::measure_bias(r.gl_set, pt.aovs, {3.0, run.file("bias_gl"), "bias_gl/"});
                     }});
  // With few cores the tasks share them better than one task's inner loops do (the comparison
  // is one thread); with many, a task alone uses them all, and a task's inner loops run serially
  // inside the group: there the tasks run one after the other.
  if (thread_count() >= kConcurrentChecksBelowThreads) {
    for (const Task& t : tasks) phases.time(t.name, t.run);
    return r;
  }
  const std::string group = "stage sets, comparison, bias (" + std::to_string(tasks.size()) + " tasks on " +
                            std::to_string(thread_count()) + " threads)";
  phases.time(group, [&] {
    parallel_tasks(int64_t(tasks.size()), [&](int64_t i) {
      Task& t = tasks[size_t(i)];
      Stopwatch sw;
      const double cpu0 = thread_cpu_ms();
      t.run();
      t.ms = sw.ms();
      t.cpu_ms = thread_cpu_ms() - cpu0;
    });
  });
  for (const Task& t : tasks) phases.add_concurrent(t.name, t.ms, t.cpu_ms);
  return r;
}

}  // namespace vct::app
