#include <wetbed/mesh/geo_constants.h>

#include <cctype>

namespace wetbed
{
namespace
{
/** The text without comments; strings are kept (a `//` inside one is not a comment). */
std::string strip_comments (const std::string &text)
{
  std::string result;
  result.reserve (text.size ());
  for (std::size_t i = 0; i < text.size ();)
  {
    if (text[i] == '"')
    {
      const std::size_t end  = text.find ('"', i + 1);
      const std::size_t stop = end == std::string::npos ? text.size () : end + 1;
      result.append (text, i, stop - i);
      i = stop;
    }
    else if (text.compare (i, 2, "//") == 0)
      i = std::min (text.find ('\n', i), text.size ());
    else if (text.compare (i, 2, "/*") == 0)
    {
      const std::size_t end = text.find ("*/", i + 2);
      i                     = end == std::string::npos ? text.size () : end + 2;
      result += ' ';
    }
    else
      result += text[i++];
  }
  return result;
}

bool identifier_char (const char c)
{
  return std::isalnum (static_cast<unsigned char> (c)) || c == '_';
}

/** The identifier ending just before `end` (skipping blanks), or "". */
std::string identifier_before (const std::string &text, std::size_t end)
{
  while (end > 0 && std::isspace (static_cast<unsigned char> (text[end - 1])))
    --end;
  std::size_t begin = end;
  while (begin > 0 && identifier_char (text[begin - 1]))
    --begin;
  if (begin == end || std::isdigit (static_cast<unsigned char> (text[begin])))
    return "";
  return text.substr (begin, end - begin);
}
} // namespace

std::set<std::string> geo_defined_constants (const std::string &geo_text)
{
  const std::string     text = strip_comments (geo_text);
  std::set<std::string> names;
  const std::string     keyword = "DefineConstant";
  for (std::size_t at = text.find (keyword); at != std::string::npos;
       at             = text.find (keyword, at + keyword.size ()))
  {
    if (at > 0 && identifier_char (text[at - 1]))
      continue;
    std::size_t i = at + keyword.size ();
    while (i < text.size () && std::isspace (static_cast<unsigned char> (text[i])))
      ++i;
    if (i == text.size () || text[i] != '[')
      continue;
    // the entries `name = ...` separated by top-level commas, up to the matching ]
    int  depth           = 0;
    bool expecting_entry = true;
    for (++i; i < text.size (); ++i)
    {
      const char c = text[i];
      if (c == '"')
      {
        const std::size_t end = text.find ('"', i + 1);
        i                     = end == std::string::npos ? text.size () - 1 : end;
      }
      else if (c == '{' || c == '(' || c == '[')
        ++depth;
      else if ((c == '}' || c == ')' || c == ']') && depth > 0)
        --depth;
      else if (c == ']')
        break;
      else if (c == ',' && depth == 0)
        expecting_entry = true;
      else if (c == '=' && depth == 0 && expecting_entry)
      {
        const std::string name = identifier_before (text, i);
        if (!name.empty ())
          names.insert (name);
        expecting_entry = false;
      }
    }
  }
  return names;
}
} // namespace wetbed
