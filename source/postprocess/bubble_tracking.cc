#include <wetbed/postprocess/bubble_tracking.h>

#include <algorithm>
#include <cmath>

namespace wetbed
{
BubbleTracker::Update BubbleTracker::update (const double                      time,
                                             const std::vector<Bubble>        &current,
                                             const std::vector<BubbleOverlap> &overlaps,
                                             const unsigned int                vertical)
{
  const unsigned int n_previous = has_previous ? previous_tracks.size () : 0;
  // successors of each previous bubble, predecessors of each current one
  std::vector<std::vector<std::pair<double, unsigned int>>> successors (n_previous),
      predecessors (current.size ());
  for (const auto &o : overlaps)
    if (o.previous < n_previous && o.current < current.size () && o.volume > 0)
    {
      successors[o.previous].emplace_back (o.volume, o.current);
      predecessors[o.current].emplace_back (o.volume, o.previous);
    }
  const auto largest = [] (const std::vector<std::pair<double, unsigned int>> &list)
  { return std::max_element (list.begin (), list.end ())->second; };

  Update result;
  result.track.resize (current.size ());
  result.rise_velocity.assign (current.size (),
                               std::numeric_limits<double>::quiet_NaN ());
  for (unsigned int i = 0; i < current.size (); ++i)
  {
    bool continued = false;
    if (!predecessors[i].empty ())
    {
      const unsigned int j = largest (predecessors[i]);
      if (largest (successors[j]) == i)
      {
        result.track[i] = previous_tracks[j];
        if (time > previous_time)
          result.rise_velocity[i] =
              (current[i].centroid[vertical] - previous_heights[j]) /
              (time - previous_time);
        continued = true;
      }
    }
    if (!continued)
      result.track[i] = next_track++;
  }
  for (unsigned int j = 0; j < n_previous; ++j)
    if (successors[j].size () > 1)
    {
      BubbleEvent event{BubbleEvent::Kind::splitting, time, {previous_tracks[j]}, {}};
      std::sort (successors[j].begin (),
                 successors[j].end (),
                 [] (auto a, auto b) { return a.second < b.second; });
      for (const auto &s : successors[j])
        event.after.push_back (result.track[s.second]);
      result.events.push_back (event);
      ++n_splittings;
    }
  for (unsigned int i = 0; i < current.size (); ++i)
    if (predecessors[i].size () > 1)
    {
      BubbleEvent event{BubbleEvent::Kind::coalescence, time, {}, {result.track[i]}};
      std::sort (predecessors[i].begin (),
                 predecessors[i].end (),
                 [] (auto a, auto b) { return a.second < b.second; });
      for (const auto &p : predecessors[i])
        event.before.push_back (previous_tracks[p.second]);
      result.events.push_back (event);
      ++n_coalescences;
    }

  previous_tracks = result.track;
  previous_heights.resize (current.size ());
  for (unsigned int i = 0; i < current.size (); ++i)
    previous_heights[i] = current[i].centroid[vertical];
  previous_time = time;
  has_previous  = true;
  return result;
}
} // namespace wetbed
