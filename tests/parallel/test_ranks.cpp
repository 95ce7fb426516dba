/// @file test_ranks.cpp
/// The rank helpers in a process started without mpirun (one rank, no MPI): the collective
/// operations as no-ops, the launcher's size from the environment. Runs on several ranks are tested through the
/// command (tests/app/test_cli_mpi.cpp).

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "sinew/parallel/ranks.hpp"

namespace sinew::parallel {
namespace {

TEST(Ranks, AProcessStartedAloneIsOneRankAndEveryCollectiveReturnsItsArgument) {
  if (launched_size() > 1) GTEST_SKIP() << "this test runs without mpirun";
  start();
  EXPECT_EQ(rank(), 0);
  EXPECT_EQ(size(), 1);
  EXPECT_TRUE(is_root());
  double values[3] = {1.5, -2, 3};
  sum(values, 3);
  EXPECT_EQ(values[0], 1.5);
  EXPECT_EQ(values[1], -2.0);
  EXPECT_EQ(sum(4.25), 4.25);
  EXPECT_EQ(max(-7.0), -7.0);
  EXPECT_TRUE(all(true));
  EXPECT_FALSE(all(false));
  EXPECT_TRUE(any(true));
  EXPECT_FALSE(any(false));
  EXPECT_EQ(broadcast(42), 42);
  EXPECT_EQ(broadcast(std::string("text")), "text");
  const ItemRange all_items = my_share(17);  // one rank takes every item
  EXPECT_EQ(all_items.begin, 0u);
  EXPECT_EQ(all_items.end, 17u);
  barrier();
  abort_all(3);  // returns: there is nothing to abort
  SUCCEED();
}

TEST(Ranks, TheLauncherSizeComesFromTheLaunchersEnvironmentAndNonsenseCountsAsOne) {
  // The launchers' variables, set aside for the test and put back after it.
  const char* names[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS", "SLURM_NTASKS"};
  std::vector<std::pair<std::string, std::string>> saved;
  for (const char* name : names) {
    if (const char* value = std::getenv(name)) saved.emplace_back(name, value);
    ::unsetenv(name);
  }
  EXPECT_EQ(launched_size(), 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  EXPECT_EQ(launched_size(), 4);
  ::setenv("OMPI_COMM_WORLD_SIZE", "four", 1);
  EXPECT_EQ(launched_size(), 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "-2", 1);
  EXPECT_EQ(launched_size(), 1);
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv("PMIX_SIZE", "8", 1);  // srun with its PMIx plugin
  EXPECT_EQ(launched_size(), 8);
  ::unsetenv("PMIX_SIZE");
  // A Slurm batch script has SLURM_NTASKS for its whole allocation, also where it starts one
  // plain process: that is no launch.
  ::setenv("SLURM_NTASKS", "8", 1);
  EXPECT_EQ(launched_size(), 1);
  ::unsetenv("SLURM_NTASKS");
  for (const auto& [name, value] : saved) ::setenv(name.c_str(), value.c_str(), 1);
}

}  // namespace
}  // namespace sinew::parallel
