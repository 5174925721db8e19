#include <wetbed/closures/drag/drag_laws.h>
#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/core/input_error.h>

namespace wetbed::closures
{
namespace
{
/** Adding a drag law: one header and one name in DragLaws (drag/drag_laws.h). */
const LawRegistry<DragModel> &registry ()
{
  static const auto laws = make_law_registry<DragModelFromLaw, DragModel> (DragLaws{});
  return laws;
}
} // namespace

std::unique_ptr<DragModel> create_drag_model (const std::string &name)
{
  const auto it = registry ().find (name);
  require (it != registry ().end (),
           "drag/model",
           "unknown drag law '" + name + "' (known: " + drag_model_names () + ")");
  return it->second ();
}

std::string drag_model_names ()
{
  std::string names;
  for (const auto &[name, factory] : registry ())
    names += (names.empty () ? "" : "|") + name;
  return names;
}
} // namespace wetbed::closures
