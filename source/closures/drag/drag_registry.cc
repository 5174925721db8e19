#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/drag/gidaspow.h>
#include <wetbed/closures/drag/no_drag.h>
#include <wetbed/closures/drag/syamlal_obrien.h>
#include <wetbed/closures/drag/wen_yu.h>
#include <wetbed/core/input_error.h>

#include <functional>
#include <map>

namespace wetbed::closures
{
namespace
{
using Factory = std::function<std::unique_ptr<DragModel> ()>;

template <class Law>
std::pair<const std::string, Factory> entry ()
{
  return {Law::name, [] { return std::make_unique<DragModelFromLaw<Law>> (); }};
}

/** Adding a drag law: one header and one line here. */
const std::map<std::string, Factory> &registry ()
{
  static const std::map<std::string, Factory> laws = {
      entry<SyamlalOBrien> (),
      entry<Gidaspow> (),
      entry<WenYu> (),
      entry<NoDrag> (),
  };
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
