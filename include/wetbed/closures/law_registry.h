#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace wetbed::closures
{
/**
 * The laws of one kind as a list of types (drag/drag_laws.h, ...): the registry of the
 * kind is built from it, and the tests iterate it (tests/closures_vectorized.cc
 * instantiates every listed law for VectorizedArray). Adding a law is one header and
 * one name in the list.
 */
template <class... Laws>
struct LawList
{
  static constexpr std::size_t size = sizeof...(Laws);
};

/** A law as a value, for for_each_law. */
template <class Law>
struct LawTag
{
  using type = Law;
};

/** f(LawTag<Law>{}) for each law of the list, in order. */
template <class... Laws, class Function>
void for_each_law (LawList<Laws...>, Function &&f)
{
  (f (LawTag<Laws>{}), ...);
}

/**
 * A registry of closure laws by name: name -> factory of the interface `Base` wrapping
 * the law.
 */
template <class Base>
using LawRegistry = std::map<std::string, std::function<std::unique_ptr<Base> ()>>;

template <template <class> class Wrapper, class Base, class... Laws>
LawRegistry<Base> make_law_registry ()
{
  return {{Laws::name, [] { return std::unique_ptr<Base> (new Wrapper<Laws> ()); }}...};
}

/** The registry of the laws of a LawList. */
template <template <class> class Wrapper, class Base, class... Laws>
LawRegistry<Base> make_law_registry (LawList<Laws...>)
{
  return make_law_registry<Wrapper, Base, Laws...> ();
}

/**
 * A registry of models that are built from settings (the solids-stress rheologies):
 * name -> factory(settings). Each model of the list has a `model_name` and a
 * `static std::unique_ptr<Base> create (const Settings &)`.
 */
template <class Base, class Settings>
using ModelRegistry =
    std::map<std::string, std::function<std::unique_ptr<Base> (const Settings &)>>;

template <class Base, class Settings, class... Models>
ModelRegistry<Base, Settings> make_model_registry (LawList<Models...>)
{
  return {{Models::model_name, [] (const Settings &settings) -> std::unique_ptr<Base> {
             return Models::create (settings);
           }}...};
}

/** Registered names of any registry, joined by '|' (for Patterns::Selection). */
template <class Registry>
std::string registered_names (const Registry &registry)
{
  std::string joined;
  for (const auto &entry : registry)
    joined += (joined.empty () ? "" : "|") + entry.first;
  return joined;
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
