// bench/instruction_counts.cpp — fixed workloads for callgrind,
// and the op counts of every generated kernel.
//
//   skelconv_bench_counts --opcounts FILE   writes every kernel's OpCount
//                                           (from the generated table) as JSON
//   skelconv_bench_counts [--smoke]         runs the regions below; under
//       valgrind --tool=callgrind each region is zeroed before and dumped
//       after (client requests), with the description "<name>|<points>",
//       and bench/summarize.py divides its instruction count by <points>.
// Without valgrind the client requests do nothing (--smoke: tiny sizes, for
// CTest).
//
// Regions (same names as the timing benchmarks; the closed forms per point,
// each segment prepared before the region, as Segment prepares it):
//   eval/<kernel>/<f|grad|f_and_grad|f+central_fd|f+forward_fd>, and
//   eval/<kernel>/f_and_grad/near
//   quadrature/<kernel>/tol:<1e-08|1e-12>[/near]
//   degree/<family>/w0/i:<i>/<f|f_and_grad>
//   generic/<kernel>/d:<d>/<beside|beyond>: the generic region
//       (bench_support.hpp: generic_region_inputs; inverse and Cauchy
//       i = 1…8, weight degree 0), split by where P's foot on the line
//       falls: on [A, B] (beside) or past an end (beyond), which decides
//       the forms the kernel takes there.
#include <valgrind/callgrind.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "bench_support.hpp"

namespace skelconv::bench {
namespace {

std::size_t kernel_points = 256;
std::size_t quadrature_points = 32;

volatile double sink;  // keeps results alive

/// Runs `body(j)` for j < n between a zero and a dump of callgrind's counters.
template <class Body>
void region(const std::string& name, std::size_t n, Body body) {
  const std::string description = name + "|" + std::to_string(n);
  CALLGRIND_ZERO_STATS;
  for (std::size_t j = 0; j < n; ++j) body(j);
  CALLGRIND_DUMP_STATS_AT(description.c_str());
}

void run_regions() {
  for (const KernelKey& key : detailed_kernels) {
    const KernelRef* k = find_kernel(key.family, key.degree, key.weight_degree);
    if (!k) continue;
    const std::vector<Input> in = make_inputs(k->family, kernel_points);
    const std::string base = "eval/" + k->name + "/";
    const PreparedPoints prepared(*k, in);
    region(base + "f", in.size(), [&](std::size_t j) { sink = prepared.f(j); });
    region(base + "grad", in.size(), [&](std::size_t j) { sink = prepared.grad(j)[0]; });
    region(base + "f_and_grad", in.size(), [&](std::size_t j) {
      Vec g;
      sink = prepared.f_and_grad(j, g) + g[0];
    });
    region(base + "f+central_fd", in.size(), [&](std::size_t j) {
      Vec g;
      sink = f_and_fd_gradient<true>(*k, in[j], g) + g[0];
    });
    region(base + "f+forward_fd", in.size(), [&](std::size_t j) {
      Vec g;
      sink = f_and_fd_gradient<false>(*k, in[j], g) + g[0];
    });
    const std::vector<Input> near = make_inputs(k->family, kernel_points, 43, near_min_distance, near_max_distance);
    const PreparedPoints prepared_near(*k, near);
    region(base + "f_and_grad/near", near.size(), [&](std::size_t j) {
      Vec g;
      sink = prepared_near.f_and_grad(j, g) + g[0];
    });
    for (bool is_near : {false, true}) {
      const std::vector<Input> qin = is_near ? make_inputs(k->family, quadrature_points, 43, near_min_distance,
                                                           near_max_distance)
                                             : make_inputs(k->family, quadrature_points);
      for (const char* tol : {"1e-08", "1e-12"}) {
        region("quadrature/" + k->name + "/tol:" + tol + (is_near ? "/near" : ""), qin.size(), [&](std::size_t j) {
          sink = quadrature(k->family, k->degree, k->weight_degree, qin[j], std::stod(tol), true).f;
        });
      }
    }
  }
  for (const KernelRef& k : generated_kernels()) {
    if (k.weight_degree != 0) continue;
    const std::vector<Input> in = make_inputs(k.family, kernel_points);
    const std::string base = "degree/" + std::string(family_name(k.family)) + "/w0/i:" + std::to_string(k.degree) + "/";
    const PreparedPoints prepared(k, in);
    region(base + "f", in.size(), [&](std::size_t j) { sink = prepared.f(j); });
    region(base + "f_and_grad", in.size(), [&](std::size_t j) {
      Vec g;
      sink = prepared.f_and_grad(j, g) + g[0];
    });
  }
  for (const KernelRef& k : generated_kernels()) {
    if (k.weight_degree != 0 || k.family == KernelFamily::compact || k.degree > 8) continue;
    for (const double d : generic_region_distances) {
      std::vector<Input> beside, beyond;
      for (const Input& in : generic_region_inputs(k.family, d)) {
        double ab_ap = 0, ab_ab = 0;
        for (int c = 0; c < 3; ++c) {
          ab_ap += (in.b[c] - in.a[c]) * (in.p[c] - in.a[c]);
          ab_ab += (in.b[c] - in.a[c]) * (in.b[c] - in.a[c]);
        }
        (ab_ap >= 0 && ab_ap <= ab_ab ? beside : beyond).push_back(in);
      }
      char distance[16];
      std::snprintf(distance, sizeof distance, "d:%g", d);
      const std::string base = "generic/" + k.name + "/" + distance + "/";
      for (const auto& [part, points] : {std::pair{"beside", &beside}, std::pair{"beyond", &beyond}}) {
        if (points->empty()) continue;
        const PreparedPoints prepared(k, *points);
        region(base + part, points->size(), [&](std::size_t j) {
          Vec g;
          sink = prepared.f_and_grad(j, g) + g[0];
        });
      }
    }
  }
}

std::string json_ops(const OpCount& o) {
  char text[200];
  std::snprintf(text, sizeof text, "{\"add\": %d, \"mul\": %d, \"div\": %d, \"sqrt\": %d, \"atan\": %d, \"log\": %d, \"other\": %d}",
                o.add, o.mul, o.div, o.sqrt, o.atan, o.log, o.other);
  return text;
}

int write_opcounts(const char* path) {
  std::ofstream out(path);
  if (!out) {
    std::fprintf(stderr, "cannot write %s\n", path);
    return 1;
  }
  out << "[\n";
  const auto& kernels = generated_kernels();
  for (std::size_t j = 0; j < kernels.size(); ++j) {
    const KernelRef& k = kernels[j];
    out << "  {\"name\": \"" << k.name << "\", \"family\": \"" << family_name(k.family) << "\", \"degree\": " << k.degree
        << ", \"weight_degree\": " << k.weight_degree << ", \"f\": " << json_ops(k.ops_f)
        << ", \"grad\": " << json_ops(k.ops_grad) << ", \"f_and_grad\": " << json_ops(k.ops_f_and_grad)
        << ", \"prepare\": " << json_ops(k.ops_prepare) << "}"
        << (j + 1 < kernels.size() ? ",\n" : "\n");
  }
  out << "]\n";
  return 0;
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  using namespace skelconv::bench;
  for (int j = 1; j < argc; ++j) {
    if (std::strcmp(argv[j], "--opcounts") == 0 && j + 1 < argc) return write_opcounts(argv[j + 1]);
    if (std::strcmp(argv[j], "--smoke") == 0) {
      kernel_points = 4;
      quadrature_points = 2;
    } else {
      std::fprintf(stderr, "usage: %s [--smoke] | --opcounts FILE\n", argv[0]);
      return 2;
    }
  }
  run_regions();
  std::printf("done: %s\n", RUNNING_ON_VALGRIND ? "under valgrind" : "not under valgrind (client requests ignored)");
  return 0;
}
