// The report's events read back from a trace: the event outputs of the multibody models only,
// each value split into element, kind, quantity and detail as messages.cpp prints them.
#include "output/report_events.hpp"

#include <catch2/catch.hpp>
#include <sstream>

#include "models/multibody/messages.hpp"
#include "support/scene_files.hpp"

using namespace yardsim;

TEST_CASE("an event value prints and parses back into its parts") {
  // (a MechanicsEvent printed by the model's own operator) => the same parts
  models::MechanicsEvent e{"setdown.rope_block", "", "clearance_below", 0.25,
                           "GOC201.upper_fore at (1, 2, 3), block at (1, 2, 2.75)"};
  std::ostringstream os;
  os << e;
  output::ReportEvent r;
  REQUIRE(output::parseEventValue(os.str(), r));
  CHECK(r.element == e.element);
  CHECK(r.what == e.what);
  CHECK(r.value == 0.25);
  CHECK(r.detail == e.detail);
  REQUIRE(output::parseEventValue("GOC201.upper_fore done 53.5 for hoist1", r));
  CHECK(r.what == "done");
  CHECK(r.value == 53.5);
  CHECK(r.detail.empty());
  CHECK_FALSE(output::parseEventValue("hoist over_mbl lots", r));
  CHECK_FALSE(output::parseEventValue("started", r));
}

TEST_CASE("only the event outputs of a trace are read and in order") {
  testing::SceneDir dir;
  const auto trace =
      dir.write("trace.jsonl", R"({"t":0,"seq":1,"model":"m","kind":"state","value":"x"}
{"t":1.5,"seq":2,"model":"m","kind":"out","port":"event","value":"hoist over_mbl 9000"}
{"t":1.5,"seq":3,"model":"a","kind":"in","port":"event","value":"hoist over_mbl 9000"}
{"t":2,"seq":4,"model":"a","kind":"out","port":"started","value":"a"}
{"t":3,"seq":5,"model":"m","kind":"out","port":"event","value":"set contact 1e-05"}
)");
  const auto events = output::reportEvents(trace);
  REQUIRE(events.size() == 2);
  CHECK(events[0].t == 1.5);
  CHECK(events[0].model == "m");
  CHECK(events[0].element == "hoist");
  CHECK(events[0].what == "over_mbl");
  CHECK(events[0].value == 9000.0);
  CHECK(events[1].what == "contact");
  CHECK(events[1].value == 1e-5);
  CHECK(output::reportEvents(trace, 1).size() == 1);  // at most the limit
  std::string json;
  output::appendEventsJson(json, events);
  CHECK(json.find("{\"t\":1.5,\"model\":\"m\",\"element\":\"hoist\",\"what\":\"over_mbl\","
                  "\"value\":9000") == 1);
}
