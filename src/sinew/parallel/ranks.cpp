#include "sinew/parallel/ranks.hpp"

// MPI's C interface only (OpenMPI's and MPICH's headers would pull in their C++ bindings).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <vector>

#include <fmt/format.h>
#ifdef SINEW_SANITIZER_BUILD
#include <sanitizer/lsan_interface.h>
#endif

#include "sinew/core/error.hpp"

namespace sinew::parallel {
namespace {

int g_rank = 0;
int g_size = 1;
bool g_started = false;

void check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error(fmt::format("MPI failed in {}: {}", call, text));
}

int environment_int(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return 0;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return (end && *end == '\0' && value > 0 && value < 1L << 30) ? static_cast<int>(value) : 0;
}

}  // namespace

int launched_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (const int n = environment_int(name)) return n;
  return 1;
}

void start() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (launched_size() <= 1) return;
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
#ifdef SINEW_SANITIZER_BUILD
      __lsan::ScopedDisabler not_ours;  // MPI's start-up state lives until the process ends
#endif
      int provided = 0;
      // Threads (TBB) work inside a rank, but only the main thread calls MPI.
      check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
      std::atexit([] {
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (finalized) return;
#ifdef SINEW_SANITIZER_BUILD
        __lsan::ScopedDisabler not_ours;
#endif
        MPI_Finalize();
      });
    }
    check(MPI_Comm_rank(MPI_COMM_WORLD, &g_rank), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &g_size), "MPI_Comm_size");
    g_started = g_size > 1;
  });
}

int rank() { return g_rank; }
int size() { return g_size; }

void sum(double* values, std::size_t n) {
  if (!g_started || n == 0) return;
  // MPI counts are ints: large arrays go in chunks.
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  for (std::size_t offset = 0; offset < n; offset += kChunk) {
    const auto count = static_cast<int>(std::min(kChunk, n - offset));
    check(MPI_Allreduce(MPI_IN_PLACE, values + offset, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  }
}

double sum(double value) {
  sum(&value, 1);
  return value;
}

double max(double value) {
  if (!g_started) return value;
  check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return value;
}

bool all(bool value) {
  if (!g_started) return value;
  int flag = value ? 1 : 0;
  check(MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD), "MPI_Allreduce");
  return flag != 0;
}

bool any(bool value) {
  if (!g_started) return value;
  int flag = value ? 1 : 0;
  check(MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
  return flag != 0;
}

int broadcast(int value) {
  if (!g_started) return value;
  check(MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return value;
}

std::string broadcast(const std::string& text) {
  if (!g_started) return text;
  const int length = broadcast(static_cast<int>(text.size()));
  std::string out = g_rank == 0 ? text : std::string(static_cast<std::size_t>(length), '\0');
  if (length > 0) check(MPI_Bcast(out.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return out;
}

std::vector<char> gather_all(const std::vector<char>& bytes) {
  if (!g_started) return bytes;
  // Every rank learns every count first, so that all of them throw together when too large.
  constexpr long long kLimit = (1LL << 31) - 1;
  const int mine = bytes.size() > static_cast<std::size_t>(kLimit) ? -1 : static_cast<int>(bytes.size());
  std::vector<int> counts(static_cast<std::size_t>(g_size));
  check(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  std::vector<int> offsets(counts.size());
  long long total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = static_cast<int>(std::min(total, kLimit));
    total += counts[r] < 0 ? kLimit + 1 : counts[r];
  }
  if (total > kLimit) throw Error(fmt::format("MPI: more than 2^31 bytes to gather from {} ranks", g_size));
  std::vector<char> all(static_cast<std::size_t>(total));
  check(MPI_Allgatherv(bytes.data(), mine, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

void barrier() {
  if (g_started) check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

void abort_all(int code) {
  if (g_started) MPI_Abort(MPI_COMM_WORLD, code);
}

ItemRange my_share(std::size_t count) { return share_of(count, g_rank, g_size); }

}  // namespace sinew::parallel
