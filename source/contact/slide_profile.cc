#include <fuzzycontact/contact/face_geometry.h>
#include <fuzzycontact/contact/slide_profile.h>

#include <algorithm>
#include <map>

namespace FuzzyContact
{
  namespace
  {
    // The angle between two unit vectors, in [0, pi].
    double
    angle_between(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return std::atan2(std::abs(a[0] * b[1] - a[1] * b[0]), a * b);
    }

    // Arc length of a face's curve between ta and tb (3-point Gauss).
    double
    arc_length(const FaceGeometry &face, const double ta, const double tb)
    {
      static const double x[3]   = {0.5 - 0.5 * std::sqrt(0.6),
                                    0.5,
                                    0.5 + 0.5 * std::sqrt(0.6)};
      static const double w[3]   = {5. / 18, 8. / 18, 5. / 18};
      double              length = 0;
      for (unsigned int q = 0; q < 3; ++q)
        length += w[q] * face.derivative(ta + x[q] * (tb - ta)).norm();
      return length * std::abs(tb - ta);
    }
  } // namespace


  double
  SlideProfile::turn_at(const double slip) const
  {
    const unsigned int         d = (slip >= 0 ? 1 : 0);
    const double               a = std::abs(slip);
    const std::vector<double> &s = arc[d];
    if (!(a <= face_end[d]))
      return INFINITY;
    Assert(!s.empty() && s.front() == 0, ExcInternalError());
    const std::size_t i = std::upper_bound(s.begin(), s.end(), a) - s.begin();
    Assert(i >= 1, ExcInternalError());
    if (i == s.size())
      return turn[d].back();
    // s[i - 1] <= a < s[i]
    const double w = (a - s[i - 1]) / (s[i] - s[i - 1]);
    return (1 - w) * turn[d][i - 1] + w * turn[d][i];
  }


  SlideProfiles::SlideProfiles(const std::vector<FaceGeometry> &faces)
      : faces_(faces)
  {
    // The faces at each end node.
    std::map<types::global_dof_index, std::vector<std::array<int, 2>>> at;
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        Assert(std::abs(faces[f].ts.front()) < 1e-12 &&
                 std::abs(faces[f].ts.back() - 1) < 1e-12,
               ExcInternalError());
        at[faces[f].nodes.front().dofs[0]].push_back({{int(f), 0}});
        at[faces[f].nodes.back().dofs[0]].push_back({{int(f), 1}});
      }
    samples_.resize(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        Samples &samples = samples_[f];
        samples.arc[0]   = 0;
        for (unsigned int i = 0; i < 5; ++i)
          {
            samples.normal[i] = faces[f].normal(i / 4.);
            if (i > 0)
              samples.arc[i] =
                samples.arc[i - 1] +
                (faces[f].straight
                   ? 0.25 * faces[f].nodes.front().position.distance(
                              faces[f].nodes.back().position)
                   : arc_length(faces[f], (i - 1) / 4., i / 4.));
          }
      }
    neighbours_.assign(faces.size(), {{{{-1, -1}}, {{-1, -1}}}});
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const FaceNode &node =
            (end == 0 ? faces[f].nodes.front() : faces[f].nodes.back());
          for (const std::array<int, 2> &other : at[node.dofs[0]])
            if (other[0] != int(f))
              neighbours_[f][end] = other;
        }
  }


  SlideProfile
  SlideProfiles::operator()(const unsigned int  face,
                            const double        t,
                            const Tensor<1, 2> &normal,
                            const Tensor<1, 2> &tangent) const
  {
    AssertIndexRange(face, faces_.size());
    SlideProfile profile;
    for (unsigned int d = 0; d < 2; ++d)
      {
        std::vector<double> &arc  = profile.arc[d];
        std::vector<double> &turn = profile.turn[d];
        arc                       = {0};
        turn                      = {0};
        double largest = 0, s = 0;
        // A turn reached at arc length s (kept only where it grows).
        const auto reach = [&](const double theta) {
          if (theta <= largest)
            return;
          if (arc.back() < s)
            {
              arc.push_back(s);
              turn.push_back(largest);
            }
          largest = theta;
          arc.push_back(s);
          turn.push_back(largest);
        };

        unsigned int f  = face;
        double       tc = t;
        // Which way along the face's parameter the slide goes.
        const double along =
          (d == 1 ? 1. : -1.) * (faces_[f].derivative(t) * tangent);
        int step = (along >= 0 ? 1 : -1);
        for (unsigned int visited = 0; visited <= faces_.size(); ++visited)
          {
            const FaceGeometry &F = faces_[f];
            if (visited == 0)
              {
                // The start face, from the projection to its end.
                const double t_end = (step > 0 ? 1. : 0.);
                if (F.straight)
                  s +=
                    F.nodes.front().position.distance(F.nodes.back().position) *
                    std::abs(t_end - tc);
                else
                  for (unsigned int i = 0; i < 4; ++i)
                    {
                      const double ta = tc + (t_end - tc) * i / 4;
                      const double tb = tc + (t_end - tc) * (i + 1) / 4;
                      s += arc_length(F, ta, tb);
                      reach(angle_between(normal, F.normal(tb)));
                    }
              }
            else
              {
                // A whole face, entered at its end tc (its samples).
                const Samples &samples = samples_[f];
                const double   s0      = s;
                for (unsigned int j = 0; j < 5; ++j)
                  {
                    const unsigned int i = (step > 0 ? j : 4 - j);
                    s                    = s0 + (step > 0 ? samples.arc[i]
                                                          : samples.arc[4] - samples.arc[i]);
                    reach(angle_between(normal, samples.normal[i]));
                  }
              }
            if (largest >= 0.5 * M_PI)
              break;
            const std::array<int, 2> &next = neighbours_[f][step > 0 ? 1 : 0];
            if (next[0] < 0)
              {
                profile.face_end[d] =
                  s + 0.1 * F.nodes.front().position.distance(
                              F.nodes.back().position);
                break;
              }
            f    = next[0];
            tc   = (next[1] == 0 ? 0. : 1.);
            step = (next[1] == 0 ? 1 : -1);
          }
        if (arc.back() < s)
          {
            arc.push_back(s);
            turn.push_back(largest);
          }
      }
    return profile;
  }
} // namespace FuzzyContact
