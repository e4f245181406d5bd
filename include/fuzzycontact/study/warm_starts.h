// The contact states of the points a study has evaluated, so that the
// next point's solve starts from its nearest neighbour's
// (contact/contact_workspace.h).
//
// A point is a vector of parameter values, compared after scaling each
// coordinate by a width (a fuzzy parameter's support): the neighbour is the
// nearest point in that scaled Euclidean distance. Only what a solver
// starts from is kept (statuses, slip directions, forces and free motions'
// amplitudes per load step), and at most a fixed number of points (the
// oldest go first). The points are kept in blocks of block_size in the
// order they came, each with the box that holds its points: an optimiser's
// consecutive points lie close together, so the boxes are small, and the
// search scans the nearest box first, then only the boxes no farther than
// the nearest point found so far. The answer is
// that of a scan over every point (the first stored of equally near
// ones), at a fraction of its cost: a scan took 10-15 us for 3000 points
// in 3 parameters, as much as a reduced evaluation of a scene with few
// contact nodes.

#ifndef fuzzycontact_study_warm_starts_h
#define fuzzycontact_study_warm_starts_h

#include <fuzzycontact/contact/contact_problem.h>

#include <cstddef>
#include <vector>

namespace FuzzyContact
{
  class WarmStarts
  {
  public:
    /**
     * @p widths: the scale of each coordinate (a zero width: the coordinate
     * does not count); @p capacity: how many points are kept.
     */
    explicit WarmStarts(const std::vector<double> &widths   = {},
                        const std::size_t          capacity = 4096);

    /** The load steps' states of the point @p x (a copy of what matters). */
    void
    add(const std::vector<double> &x, const std::vector<ContactState> &states);

    /**
     * The states of the point nearest to @p x, or null if there is none.
     * Valid until the next add().
     */
    const std::vector<ContactState> *
    nearest(const std::vector<double> &x) const;

    std::size_t
    size() const;

  private:
    // Coordinate i of x scaled by 1 / widths[i] (0 where widths[i] is 0).
    void
    scale(const std::vector<double> &x, std::vector<double> &scaled) const;

    std::vector<double> widths;
    std::size_t         capacity;
    unsigned int        dimension = 0;
    // A ring of at most capacity points: their scaled coordinates, one
    // after the other, and their states; next: where the next point goes.
    std::vector<double>                    coordinates;
    std::vector<std::vector<ContactState>> states;
    std::size_t                            next = 0;
    // Per block of block_size points (in storage order), the smallest and
    // largest scaled coordinates of its points (dimension each).
    static constexpr std::size_t block_size = 32;
    std::vector<double>          box_low, box_high;
    void
                                update_box(const std::size_t block);
    mutable std::vector<double> scaled_x;
    // The (squared) distance from the point searched to each block's box.
    mutable std::vector<double> box_distance;
  };
} // namespace FuzzyContact

#endif
