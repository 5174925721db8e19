#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace wetbed::closures
{
/**
 * A registry of closure laws by name: name -> factory of the interface `Base` wrapping
 * the law. Adding a law is one header and one name in the make_law_registry<...> list.
 */
template <class Base>
using LawRegistry = std::map<std::string, std::function<std::unique_ptr<Base> ()>>;

template <template <class> class Wrapper, class Base, class... Laws>
LawRegistry<Base> make_law_registry ()
{
  return {{Laws::name, [] { return std::unique_ptr<Base> (new Wrapper<Laws> ()); }}...};
}

/** The law registered under `name`; std::invalid_argument naming `what` if none. */
template <class Base>
std::unique_ptr<Base>
create_law (const LawRegistry<Base> &registry, const std::string &name, const char *what)
{
  const auto it = registry.find (name);
  if (it == registry.end ())
    throw std::invalid_argument (std::string ("unknown ") + what + " '" + name + "'");
  return it->second ();
}

/** Registered names joined by '|' (for Patterns::Selection). */
template <class Base>
std::string law_names (const LawRegistry<Base> &registry)
{
  std::string joined;
  for (const auto &entry : registry)
    joined += (joined.empty () ? "" : "|") + entry.first;
  return joined;
}
} // namespace wetbed::closures
