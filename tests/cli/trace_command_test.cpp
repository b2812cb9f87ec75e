// yardsim trace, as a process: its file and time window are inputs refused with exit 1 (found by
// the mutation experiment, tests/fuzz/mutate.py: `trace /dev/zero` read a line without end,
// `--from nan` showed nothing with exit 0, a record with `"t": "abc"` was an internal error).
#include <catch2/catch.hpp>

#include "support/scene_files.hpp"
#include "support/shell_command.hpp"

namespace {

// (arguments) => exit status and output of `yardsim trace arguments`, killed after 20 s
yardsim::testing::ShellResult trace(const std::string& args) {
  return yardsim::testing::shell(std::string(YARDSIM_EXE) + " trace " + args, 20);
}

}  // namespace

TEST_CASE("yardsim trace refuses a file that is not a regular file (exit 1)") {
  yardsim::testing::SceneDir dir;
  for (const std::string file : {std::string("/dev/zero"), dir.path().string()}) {
    const auto r = trace(file);
    INFO(r.out);
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("'" + file + "' is not a regular file"));
  }
}

TEST_CASE("yardsim trace refuses a time window that is not a finite time (exit 1)") {
  yardsim::testing::SceneDir dir;
  const auto file =
      dir.write("t.jsonl", "{\"t\": 1.5, \"model\": \"a\", \"kind\": \"out\", \"port\": \"p\"}\n");
  for (const std::string bad : {"--from nan", "--to inf", "--from -1", "--to abc"}) {
    const auto r = trace(file.string() + " " + bad);
    INFO(bad << ": " << r.out);
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains(bad.substr(0, 4)));
  }
  const auto r = trace(file.string() + " --from 1 --to 2");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("1 of 1"));
}

TEST_CASE("yardsim trace names the line of a record whose fields have the wrong type (exit 1)") {
  yardsim::testing::SceneDir dir;
  for (const std::string record :
       {R"({"t": "abc", "model": "a", "kind": "out"})", R"({"t": 1, "model": [a], "kind": "out"})",
        R"({"t": 1, "model": "a", "kind": "out", "port": {p: 1}})"}) {
    const auto file =
        dir.write("t.jsonl", "{\"t\": 0, \"model\": \"a\", \"kind\": \"out\"}\n" + record + "\n");
    const auto r = trace(file.string());
    INFO(record << ": " << r.out);
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("t.jsonl:2: not a yardsim trace record"));
  }
}
