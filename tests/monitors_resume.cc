// monitors.csv across a resume: cut back to the checkpoint's length, and a file written
// with other columns (an earlier version, other probe heights) rewritten under the
// current header, each value moved to its column by name, new columns left empty and
// the run column (an older file has none) given the run's id.
#include "test_utilities.h"

#include <wetbed/postprocess/monitors.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wetbed;
using wetbed::testing::check;

namespace
{
std::vector<std::string> lines_of (const std::string &file)
{
  std::ifstream            in (file);
  std::vector<std::string> lines;
  for (std::string line; std::getline (in, line);)
    lines.push_back (line);
  return lines;
}

std::vector<std::string> fields (const std::string &line)
{
  std::vector<std::string> out;
  std::istringstream       in (line);
  for (std::string f; std::getline (in, f, ',');)
    out.push_back (f);
  if (!line.empty () && line.back () == ',')
    out.emplace_back ();
  return out;
}
} // namespace

int main ()
{
  const std::string file = "monitors_resume.csv";
  const std::string id   = "00c0ffee12345678";
  MonitorRow        row;
  row.fluidization        = 1.25;
  row.wall_support_solids = -0.5;
  row.plane_alpha         = {0.3};

  // same columns: the rows after the checkpoint are dropped, the run appends
  {
    Monitors m;
    m.open (file, true, {{0.076}, {}, 0}, id);
    row.step = 1;
    m.add (row);
    row.step = 2;
    m.add (row);
  }
  {
    Monitors   m;
    const auto before = lines_of (file);
    check (before.size () == 3, "three lines before the resume");
    // the length after the first row, as the checkpoint stored it
    const unsigned long long bytes = before[0].size () + 1 + before[1].size () + 1;
    m.reopen (file, true, bytes, {{0.076}, {}, 0}, id);
    row.step = 7;
    m.add (row);
  }
  auto lines = lines_of (file);
  check (lines.size () == 3 && fields (lines[1])[0] == "1" && fields (lines[2])[0] == "7",
         "resume with the same columns: row 2 dropped, row 7 appended");
  check (fields (lines[0]).back () == "run" && fields (lines[1]).back () == id &&
             fields (lines[2]).back () == id,
         "the last column is run, every row carries the run's id");

  // an older file without the budget columns and the run column and with the plane
  // column where it was: written by hand from the current header less five columns
  const std::vector<std::string> names = fields (lines[0]);
  std::vector<std::string>       old_names;
  for (const auto &n : names)
    if (n.rfind ("wall_support", 0) != 0 && n != "distributor_support" &&
        n != "outlet_support" && n != "run")
      old_names.push_back (n);
  check (old_names.size () + 5 == names.size (),
         "the current header has the four budget columns and the run column");
  {
    std::ofstream out (file);
    for (std::size_t c = 0; c < old_names.size (); ++c)
      out << (c ? "," : "") << old_names[c];
    out << '\n';
    for (int r = 0; r < 2; ++r)
    {
      for (std::size_t c = 0; c < old_names.size (); ++c)
        out << (c ? "," : "")
            << (old_names[c] == "step"                  ? std::to_string (r + 1)
                : old_names[c] == "alpha_s_plane_0.076" ? "0.55"
                                                        : "9");
      out << '\n';
    }
  }
  const unsigned long long full = std::filesystem::file_size (file);
  {
    Monitors m;
    m.reopen (file, true, full, {{0.076}, {}, 0}, id);
    row.step = 3;
    m.add (row);
  }
  lines = lines_of (file);
  check (lines.size () == 4, "header, two old rows and the new one after the rewrite");
  check (
      lines[0] ==
          [&]
          {
            std::string h;
            for (std::size_t c = 0; c < names.size (); ++c)
              h += (c ? "," : "") + names[c];
            return h;
          }(),
      "the rewritten file has the current header");
  bool old_rows_ok = true, new_row_ok = true;
  for (int r = 1; r <= 2; ++r)
  {
    const auto values = fields (lines[r]);
    old_rows_ok       = old_rows_ok && values.size () == names.size ();
    for (std::size_t c = 0; c < names.size () && c < values.size (); ++c)
    {
      const bool budget = names[c].rfind ("wall_support", 0) == 0 ||
                          names[c] == "distributor_support" ||
                          names[c] == "outlet_support";
      const std::string expected = budget               ? ""
                                   : names[c] == "run"  ? id
                                   : names[c] == "step" ? std::to_string (r)
                                   : names[c] == "alpha_s_plane_0.076" ? "0.55"
                                                                       : "9";
      old_rows_ok                = old_rows_ok && values[c] == expected;
    }
  }
  const auto values = fields (lines[3]);
  for (std::size_t c = 0; c < names.size (); ++c)
  {
    if (names[c] == "fluidization_index")
      new_row_ok = new_row_ok && values[c] == "1.25";
    if (names[c] == "wall_support_solids")
      new_row_ok = new_row_ok && values[c] == "-0.5";
    if (names[c] == "alpha_s_plane_0.076")
      new_row_ok = new_row_ok && values[c] == "0.3";
    if (names[c] == "run")
      new_row_ok = new_row_ok && values[c] == id;
  }
  check (old_rows_ok,
         "old rows: every value under its own name, the budget columns empty, the "
         "run column the run's id");
  check (new_row_ok && values.size () == names.size (),
         "the row after the resume is written under the current header");
  std::filesystem::remove (file);
  return wetbed::testing::finish ("monitors_resume");
}
