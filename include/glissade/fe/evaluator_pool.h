#pragma once

#include <glissade/fe/cell_evaluator.h>
#include <glissade/fe/element_space.h>

#include <memory>
#include <mutex>
#include <vector>

namespace glissade
{
  class EvaluatorPool;

  /** Gives a borrowed evaluator back to its pool. */
  struct EvaluatorReturn
  {
    EvaluatorPool *pool = nullptr;
    void
    operator()(CellEvaluator *evaluator) const;
  };

  /** An evaluator that goes back to its pool when it goes. */
  using BorrowedEvaluator = std::unique_ptr<CellEvaluator, EvaluatorReturn>;

  /**
   * The evaluators of one element space's own rule, made once and lent:
   * an assembly (the scratch of each of its threads, the boundary
   * evaluator) builds no FEValues, which on a small body cost as much as
   * integrating its cells. Safe on several threads. The pool must go
   * before the space (the evaluators point at its element and mapping):
   * its owner declares it after the space.
   */
  class EvaluatorPool
  {
  public:
    explicit EvaluatorPool(const ElementSpace &space);

    /** An idle evaluator, or a new one. */
    BorrowedEvaluator
    borrow();

  private:
    friend struct EvaluatorReturn;
    const ElementSpace                         &space;
    std::vector<std::unique_ptr<CellEvaluator>> idle;
    std::mutex                                  mutex;
  };
} // namespace glissade
