#pragma once
/// @file root_for_all.hpp
/// Work that only rank 0 does for all ranks (checking the output directory, meshing a body):
/// its failure must stop every rank the same way, or the others would wait for it forever
/// (docs/mpi.md).

#include <functional>

namespace sinew::parallel {

/// Runs `step` on rank 0 only. When it throws, every rank throws: rank 0 its own exception, the
/// others one of the same kind (InputError, OutputError, OutOfMemoryError or Error) with the same
/// message. On one rank: just runs `step`.
void on_root_for_all(const std::function<void()>& step);

}  // namespace sinew::parallel
