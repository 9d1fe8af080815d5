// Soft bodies (issue 28) for the bench report's "Soft bodies" section.
//
// Google Benchmark BM_SoftStep/nodes:N/fingers:F: one step of a soft cube (10 cm, E 50 kPa,
// nu 0.45, 1 kg, glued by its bottom face; soft/block_mesh.h's mesh of about N nodes graded 3
// toward the top centre) held pressed by F pads of radius 1 cm (1 N each, at the top centre and
// 2 cm beside it, wavering by 0.1 N at 2 Hz so that the body never sleeps), as the physics will
// step it: the pads' pressure on the current surface (soft/surface_load.h), then the implicit
// step (soft/elastic_body.h). Counters: p50_us, p99_us of the timed steps (manual time), nodes,
// factor_nnz (the step's factor), setup_s (factoring), slept (1 if the body fell asleep: then
// the timing is not a step's).
//
// With --fidelity [NODES...] (no Google Benchmark): one JSON line per mesh (216, 512, 1000, 1728, 2744 and 5832
// nodes unless given): scenarios/soft_press_fidelity.h's pad and point sinks against Boussinesq's w0 and the
// plate check, with the median of 300 one-pad steps at that mesh (step_p50_us): the error against
// the step cost, measured in one run.
// Units: SI, times in us. Not real-time.
#include "god_finger/scenarios/soft_press_fidelity.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/soft/surface_load.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <vector>

namespace god_finger
{
namespace
{
using Clock = std::chrono::steady_clock;

struct SoftCube
{
  std::unique_ptr<ElasticBody> body;
  double setup_s = 0.0;
};

// One cube per size, built (and factored) once per process.
SoftCube& cube(int nodes)
{
  static std::map<int, SoftCube> cubes;
  SoftCube& entry = cubes[nodes];
  if (!entry.body)
  {
    BlockMeshSpec spec;
    const int cells = cubeCellsForNodes(nodes);
    spec.cells = {cells, cells, cells};
    spec.grading = 3.0;
    TetMesh mesh = blockTetMesh(spec);
    SoftMaterial material;
    material.young_modulus = 50e3;
    material.poisson_ratio = 0.45;
    material.density = 1000.0;
    material.stiffness_damping = 0.01;
    const std::vector<int> bottom = nodesAtHeight(mesh, 0.0, 1e-12);
    const Clock::time_point start = Clock::now();
    entry.body = std::make_unique<ElasticBody>(std::move(mesh), material, bottom, 1e-3, Eigen::Vector3d(0, 0, -9.81));
    entry.setup_s = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return entry;
}

// One step of a press that a hand holds (1 N, wavering by 0.1 N at 2 Hz: a held press never
// stands still, so the body never sleeps): the pads' pressure on the current surface, then the
// step. Returns seconds.
double pressStep(ElasticBody& body, int fingers, int step, Eigen::VectorXd& forces,
                 std::vector<Eigen::Vector3d>& positions)
{
  const double newtons = 1.0 + 0.1 * std::sin(2.0 * M_PI * 2.0 * step * body.timeStep());
  const Clock::time_point start = Clock::now();
  body.positions(&positions);
  forces.setZero();
  for (int finger = 0; finger < fingers; ++finger)
  {
    PadDisk pad;
    pad.centre = Eigen::Vector3d(0.02 * finger, 0.0, 0.1);
    pad.radius = 0.01;
    addPadPressure(positions, body.surface(), pad, Eigen::Vector3d(0.0, 0.0, -newtons), &forces);
  }
  body.step(forces);
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void BM_SoftStep(benchmark::State& state)
{
  const int nodes = static_cast<int>(state.range(0));
  const int fingers = static_cast<int>(state.range(1));
  SoftCube& entry = cube(nodes);
  ElasticBody& body = *entry.body;
  body.reset();
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> times;
  int step = 0;
  for (auto _ : state)
  {
    const double seconds = pressStep(body, fingers, step++, forces, positions);
    state.SetIterationTime(seconds);
    times.push_back(seconds);
  }
  std::sort(times.begin(), times.end());
  state.counters["p50_us"] = 1e6 * times[times.size() / 2];
  state.counters["p99_us"] = 1e6 * times[std::min(times.size() - 1, times.size() * 99 / 100)];
  state.counters["nodes"] = body.nodeCount();
  state.counters["factor_nnz"] = static_cast<double>(body.factorNonZeros());
  state.counters["setup_s"] = entry.setup_s;
  state.counters["slept"] = body.sleeping() ? 1.0 : 0.0;
}

void fidelity(const std::vector<int>& meshes)
{
  for (int nodes : meshes)
  {
    SoftPressSetup setup;
    setup.nodes = nodes;
    setup.grading = 3.0;
    const SoftPressResult result = pressSoftBlock(setup);
    ElasticBody& body = *cube(nodes).body;
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
    std::vector<Eigen::Vector3d> positions;
    std::vector<double> times;
    for (int step = 0; step < 300; ++step)
    {
      times.push_back(pressStep(body, 1, step, forces, positions));
    }
    std::sort(times.begin(), times.end());
    std::string line = softPressJson(setup, result);
    line.pop_back();
    std::printf("%s, \"step_p50_us\": %.1f}\n", line.c_str(), 1e6 * times[times.size() / 2]);
    std::fflush(stdout);
  }
}
}  // namespace
}  // namespace god_finger

using god_finger::BM_SoftStep;  // the report's name: BM_SoftStep/nodes:N/fingers:F
BENCHMARK(BM_SoftStep)
    ->ArgNames({"nodes", "fingers"})
    ->Args({250, 1})
    ->Args({250, 2})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Args({4000, 1})
    ->Args({4000, 2})
    ->Args({16000, 1})
    ->Args({16000, 2})
    ->UseManualTime()
    ->MinTime(0.3)
    ->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv)
{
  if (argc >= 2 && std::strcmp(argv[1], "--fidelity") == 0)
  {
    std::vector<int> meshes;
    for (int i = 2; i < argc; ++i)
    {
      meshes.push_back(std::atoi(argv[i]));
    }
    god_finger::fidelity(meshes.empty() ? std::vector<int>{216, 512, 1000, 1728, 2744, 5832} : meshes);
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
