#include "support/executor_scope.hpp"

namespace obbsat::detail {

namespace {

thread_local const executor* executor_in_scope = nullptr;

}  // namespace

executor_scope::executor_scope(const executor* given) : replaced_(executor_in_scope) {
    executor_in_scope = given;
}

executor_scope::~executor_scope() { executor_in_scope = replaced_; }

const executor* executor_scope::current() { return executor_in_scope; }

}  // namespace obbsat::detail
