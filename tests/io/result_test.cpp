#include "ossa/io/result.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "ossa/level/level_io.h"

using namespace ossa;

namespace {

struct ChildRun {
  bool aborted = false;  // ended by SIGABRT
  std::string err;       // what it wrote to stderr
};

// Runs `body` in a forked child with its stderr captured (a death test: the child aborts).
template <class F>
ChildRun run_in_child(F body) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDERR_FILENO);
    body();
    _exit(0);
  }
  close(fds[1]);
  ChildRun run;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) run.err.append(buf, static_cast<size_t>(n));
  close(fds[0]);
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  run.aborted = WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
  return run;
}

}  // namespace

TEST_CASE("Result::value() on an error prints the error's own message, then aborts", "[io]") {
  SECTION("an error made by hand") {
    const ChildRun run = run_in_child([] {
      Result<int> r = Error::at("levels/foo.json", "colliders[3].size.x", "expected a number >= 0, got -2");
      std::printf("%d\n", r.value());
    });
    CHECK(run.aborted);
    CHECK(run.err ==
          "Result::value() on an error: levels/foo.json: colliders[3].size.x: expected a number >= 0, got -2\n");
  }
  SECTION("a missing level file names its path") {
    const ChildRun run = run_in_child([] {
      const Level level = load_level("/nonexistent/ossa/level.json").value();
      std::printf("%d\n", level.size());
    });
    CHECK(run.aborted);
    CHECK_THAT(run.err, Catch::Matchers::StartsWith("Result::value() on an error: /nonexistent/ossa/level.json"));
  }
  SECTION("a value is returned without a word") {
    const ChildRun run = run_in_child([] {
      Result<std::string> r = std::string("fine");
      if (r.value() != "fine") std::abort();
    });
    CHECK_FALSE(run.aborted);
    CHECK(run.err.empty());
  }
}
