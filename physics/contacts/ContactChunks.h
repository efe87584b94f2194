#pragma once
// ContactSolver::forChunks, for the solver's source files (private to physics/contacts).

#include "physics/contacts/ContactSolver.h"
#include "physics/core/WorkerPool.h"

namespace phasebox {

template <class F>
void ContactSolver::forChunks(std::size_t count, std::size_t grain, const F& fn) {
    if (count == 0) return;
    if (!pool_ || count <= grain) {
        fn(std::size_t{0}, count);
        return;
    }
    pool_->parallelFor(static_cast<int>(count), static_cast<int>(grain),
                       [&fn](int begin, int end, int) {
                           fn(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
                       });
}

}  // namespace phasebox
