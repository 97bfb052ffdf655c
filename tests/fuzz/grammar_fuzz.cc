// libFuzzer target for the case files' list grammar and what reads it (issue 15, item 3):
// parse_spec_list splits an entry into items and fields, parse_numbers reads every field value,
// and each item is also evaluated as a closed form (name = item name, arguments = its keyed
// numeric fields), so the formulas' validation and root finders see arbitrary, hostile
// arguments (NaN, inf, huge, negative). Contract: std::invalid_argument (or std::domain_error /
// std::out_of_range for values the formulas cannot take) and nothing else; no crash, no hang,
// no sanitizer report. Run by tests/fuzz/run_fuzz.sh.
#include <closed_forms/registry.h>

#include "input/spec_list.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char *>(data), size);
  std::vector<compliant::SpecItem> items;
  try
    {
      items = compliant::parse_spec_list(text, "fuzz");
    }
  catch (const std::invalid_argument &)
    {
      return 0;
    }
  for (const auto &item : items)
    {
      std::map<std::string, double> arguments;
      for (const auto &field : item.fields)
        try
          {
            const auto values = compliant::parse_numbers(field.value, "fuzz");
            if (!field.key.empty() && values.size() == 1)
              arguments[field.key] = values[0];
          }
        catch (const std::invalid_argument &)
          {
          }
      try
        {
          (void)compliant::round_trip_text(arguments.empty() ? 0.0 : arguments.begin()->second);
          (void)closed_forms::evaluate(item.name, arguments);
        }
      catch (const std::invalid_argument &)
        {
        }
      catch (const std::domain_error &)
        {
        }
      catch (const std::out_of_range &)
        {
        }
    }
  return 0;
}
