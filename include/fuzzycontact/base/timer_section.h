// A TimerOutput section that is timed only if there is a timer: the
// library's stages take an optional TimerOutput * (nullptr: not timed).

#ifndef fuzzycontact_base_timer_section_h
#define fuzzycontact_base_timer_section_h

#include <deal.II/base/timer.h>

#include <memory>
#include <string>

namespace FuzzyContact
{
  /**
   * A scope timing @p section in @p timer until it is destroyed; empty if
   * @p timer is nullptr.
   */
  inline std::unique_ptr<dealii::TimerOutput::Scope>
  timer_section(dealii::TimerOutput *timer, const std::string &section)
  {
    return timer != nullptr
             ? std::make_unique<dealii::TimerOutput::Scope>(*timer, section)
             : std::unique_ptr<dealii::TimerOutput::Scope>();
  }
} // namespace FuzzyContact

#endif
