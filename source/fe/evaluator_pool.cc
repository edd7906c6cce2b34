// The evaluators of an element space, made once and lent
// (include/glissade/fe/evaluator_pool.h).

#include <glissade/fe/evaluator_pool.h>

namespace glissade
{
  void
  EvaluatorReturn::operator()(CellEvaluator *evaluator) const
  {
    std::lock_guard<std::mutex> lock(pool->mutex);
    pool->idle.emplace_back(evaluator);
  }



  EvaluatorPool::EvaluatorPool(const ElementSpace &space)
    : space(space)
  {}



  BorrowedEvaluator
  EvaluatorPool::borrow()
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!idle.empty())
        {
          CellEvaluator *evaluator = idle.back().release();
          idle.pop_back();
          return BorrowedEvaluator(evaluator, EvaluatorReturn{this});
        }
    }
    return BorrowedEvaluator(space.create_evaluator().release(),
                             EvaluatorReturn{this});
  }
} // namespace glissade
