#include <glissade/contact/step/condensed_step.h>
#include <glissade/contact/step/contact_step.h>
#include <glissade/contact/step/sparse_contact_step.h>

#include <functional>

namespace glissade
{
  std::unique_ptr<ContactStep>
  ContactStep::create(const ContactSolverSettings::Method method,
                      const ContactStepContext           &context)
  {
    // One line per method.
    using Method = ContactSolverSettings::Method;
    static const std::vector<std::pair<
      Method,
      std::function<std::unique_ptr<ContactStep>(const ContactStepContext &)>>>
      steps = {{Method::condensed,
                [](const ContactStepContext &c) {
                  return std::make_unique<CondensedStep>(c);
                }},
               {Method::sparse, [](const ContactStepContext &c) {
                  return std::make_unique<SparseContactStep>(c);
                }}};
    for (const auto &[m, create] : steps)
      if (m == method)
        return create(context);
    return nullptr;
  }
} // namespace glissade
