#pragma once
// The multibody models' events as the report shows them (docs/report.md): read back from the
// `event` outputs of trace.jsonl (full or `events` trace), whose value is a MechanicsEvent as
// models/multibody/messages.cpp prints it: "ELEMENT WHAT VALUE[ for ACTOR][ (DETAIL)]". The page
// puts markers at the alarms' occurrences and names the pair of a clearance's closest approach.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace yardsim::output {

struct ReportEvent {
  double t = 0.0;     // s
  std::string model;  // the multibody model's path
  std::string element, what;
  double value = 0.0;  // SI, the event's quantity
  std::string detail;  // provider events: the pair and witness points ("" for none)
};

// (one event value as printed) => its parts; false when it is not of that form
bool parseEventValue(const std::string& value, ReportEvent& out);

// (trace.jsonl, at most this many) => the `event` outputs, in the trace's order
std::vector<ReportEvent> reportEvents(const std::filesystem::path& traceJsonl,
                                      std::size_t limit = 20000);

// (events) => a JSON array of {t, model, element, what, value, detail}
void appendEventsJson(std::string& out, const std::vector<ReportEvent>& events);

}  // namespace yardsim::output
