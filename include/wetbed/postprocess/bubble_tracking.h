#pragma once

#include <wetbed/postprocess/bubble_detection.h>

#include <limits>
#include <string>
#include <vector>

namespace wetbed
{
/** A splitting (one bubble into several) or a coalescence (several into one). */
struct BubbleEvent
{
  enum class Kind
  {
    splitting,
    coalescence
  };
  Kind                      kind;
  double                    time = 0;
  std::vector<unsigned int> before, after; // track ids
};

/** An overlap between a bubble of this analysis and one of the previous analysis. */
struct BubbleOverlap
{
  unsigned int current, previous;
  double       volume; // of the cells the two share
};

/**
 * Follows bubbles from one analysis to the next by overlap: a bubble continues the track
 * of the previous bubble it shares most volume with (if it is also that bubble's largest
 * successor); a previous bubble that overlaps several current ones split, a current
 * bubble that overlaps several previous ones is a coalescence. Rise velocity: the
 * upward displacement of the centroid of a continued track over the time between the
 * analyses.
 */
class BubbleTracker
{
public:
  struct Update
  {
    std::vector<unsigned int> track;         // per current bubble
    std::vector<double>       rise_velocity; // NaN for a new track
    std::vector<BubbleEvent>  events;
  };

  /** `vertical`: the coordinate that points up (1 in 2D, 2 in 3D for gravity along -y,
   * -z). Every rank calls it with the same data. */
  Update update (double                            time,
                 const std::vector<Bubble>        &current,
                 const std::vector<BubbleOverlap> &overlaps,
                 unsigned int                      vertical);

  unsigned long long splittings () const { return n_splittings; }
  unsigned long long coalescences () const { return n_coalescences; }

  template <class Archive>
  void serialize (Archive &archive, const unsigned int)
  {
    archive &previous_tracks &previous_heights &previous_time &next_track &n_splittings;
    archive &n_coalescences                                               &has_previous;
  }

private:
  std::vector<unsigned int> previous_tracks;
  std::vector<double>       previous_heights; // centroid heights
  double                    previous_time  = 0;
  unsigned int              next_track     = 0;
  unsigned long long        n_splittings   = 0;
  unsigned long long        n_coalescences = 0;
  bool                      has_previous   = false;
};
} // namespace wetbed
