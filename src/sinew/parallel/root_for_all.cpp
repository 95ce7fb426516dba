#include "sinew/parallel/root_for_all.hpp"

#include <exception>
#include <new>
#include <string>

#include "sinew/core/error.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::parallel {

namespace {

/// The kinds of failure on_root_for_all passes from rank 0 to the others.
enum class FailureKind : int { None = 0, Input = 1, Output = 2, Memory = 3, Other = 4 };

}  // namespace

void on_root_for_all(const std::function<void()>& step) {
  if (size() <= 1) {
    step();
    return;
  }
  FailureKind kind = FailureKind::None;
  std::string message;
  std::exception_ptr failure;
  if (is_root()) {
    try {
      step();
    } catch (const InputError& e) {
      kind = FailureKind::Input, message = e.what(), failure = std::current_exception();
    } catch (const OutputError& e) {
      kind = FailureKind::Output, message = e.what(), failure = std::current_exception();
    } catch (const OutOfMemoryError& e) {
      kind = FailureKind::Memory, message = e.what(), failure = std::current_exception();
    } catch (const std::bad_alloc&) {
      kind = FailureKind::Memory, message = "out of memory", failure = std::current_exception();
    } catch (const std::exception& e) {
      kind = FailureKind::Other, message = e.what(), failure = std::current_exception();
    }
  }
  kind = static_cast<FailureKind>(broadcast(static_cast<int>(kind)));
  if (kind == FailureKind::None) return;
  message = broadcast(message);
  if (failure) std::rethrow_exception(failure);
  switch (kind) {
    case FailureKind::Input: throw InputError(message);
    case FailureKind::Output: throw OutputError(message);
    case FailureKind::Memory: throw OutOfMemoryError(message);
    default: throw Error(message);
  }
}

}  // namespace sinew::parallel
