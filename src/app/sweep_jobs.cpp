#include "app/sweep_jobs.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>

#include "core/error.hpp"

extern char** environ;

namespace camouflet::app {

namespace {

using Clock = std::chrono::steady_clock;

std::string failure_message(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last, last_error;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.starts_with("error:")) last_error = line;
  }
  return last_error.empty() ? last : last_error;
}

// Starts the child with its output in job.log; -1 (and a message) when it cannot be started.
pid_t spawn(SweepJob& job) {
  const std::string exe = self_executable().string();
  std::vector<std::string> args{exe};
  args.insert(args.end(), job.arguments.begin(), job.arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    job.status = exit_io_failure;
    job.message = std::string("cannot start the run: ") + std::strerror(rc);
    return -1;
  }
  return pid;
}

}  // namespace

std::filesystem::path self_executable() {
  std::error_code ec;
  return std::filesystem::read_symlink("/proc/self/exe", ec);
}

void run_sweep_jobs(std::vector<SweepJob>& list, int jobs, const std::function<bool(std::size_t)>& started,
                    const std::function<void(std::size_t)>& done) {
  std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running;
  std::size_t next = 0;
  while (next < list.size() || !running.empty()) {
    while (next < list.size() && static_cast<int>(running.size()) < jobs) {
      const std::size_t i = next++;
      const Clock::time_point t0 = Clock::now();
      if (!started(i)) {
        done(i);
        continue;
      }
      const pid_t pid = spawn(list[i]);
      if (pid < 0) {
        done(i);
        continue;
      }
      running[pid] = {i, t0};
    }
    if (running.empty()) continue;
    int raw = 0;
    const pid_t pid = waitpid(-1, &raw, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      // No child left to wait for (cannot happen while `running` is not empty): give up on them.
      for (auto& [p, job] : running) {
        list[job.first].status = exit_io_failure;
        list[job.first].message = "lost track of the run process";
        done(job.first);
      }
      running.clear();
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    SweepJob& job = list[it->second.first];
    job.wall_seconds = std::chrono::duration<double>(Clock::now() - it->second.second).count();
    job.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + (WIFSIGNALED(raw) ? WTERMSIG(raw) : 0);
    if (job.status != 0) {
      job.message = failure_message(job.log);
      if (WIFSIGNALED(raw))
        job.message = "killed by signal " + std::to_string(WTERMSIG(raw)) +
                      (job.message.empty() ? "" : ": " + job.message);
    }
    const std::size_t index = it->second.first;
    running.erase(it);
    done(index);
  }
}

}  // namespace camouflet::app
