// f over many expressions in forked processes.
#include "unidyn/symbolic/process_map.hpp"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include "unidyn/symbolic/expression_transport.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// A task is a run of consecutive expressions of the queue's order; at most this many tasks, so
// that all their numbers fit in a pipe's buffer before anyone reads (64 KiB on Linux).
constexpr std::size_t kMaxTasks = 4096;

// A pipe's two ends, closed when dropped.
struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error("pipe2 failed");
    read = ends[0];
    write = ends[1];
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  ~Pipe() {
    close_read();
    close_write();
  }
  void close_read() {
    if (read >= 0) ::close(read);
    read = -1;
  }
  void close_write() {
    if (write >= 0) ::close(write);
    write = -1;
  }
};

// All of `bytes` written to `fd` (false: it could not be).
bool write_all(int fd, const char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= std::size_t(n);
  }
  return true;
}

// Everything `fd` gives until its end.
std::string read_all(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, std::size_t(n));
  }
}

// The next task's number from the queue, or −1 when it is empty.
std::int64_t next_task(int queue) {
  std::uint32_t task;
  for (;;) {
    const ssize_t n = ::read(queue, &task, sizeof task);
    if (n < 0 && errno == EINTR) continue;
    return n == ssize_t(sizeof task) ? std::int64_t(task) : -1;
  }
}

// The forked copies: killed and waited for when dropped before they were collected.
struct Copies {
  std::vector<pid_t> pids;
  ~Copies() {
    for (const pid_t pid : pids) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    }
  }
};

void put(std::string& bytes, std::uint64_t n) {
  bytes.append(reinterpret_cast<const char*>(&n), sizeof n);
}

bool take(std::string_view& bytes, std::uint64_t& n) {
  if (bytes.size() < sizeof n) return false;
  std::copy_n(bytes.data(), sizeof n, reinterpret_cast<char*>(&n));
  bytes.remove_prefix(sizeof n);
  return true;
}

}  // namespace

std::size_t worker_processes() {
  if (const char* set = std::getenv("UNIDYN_PROCESSES"); set != nullptr) {
    const std::string text = set;
    std::size_t n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error != std::errc() || end != text.data() + text.size() || n == 0) {
      throw std::invalid_argument("UNIDYN_PROCESSES must be a positive integer, not '" + text +
                                  "'");
    }
    return n;
  }
  cpu_set_t cores;
  if (::sched_getaffinity(0, sizeof cores, &cores) != 0) return 1;
  return std::size_t(std::max(1, CPU_COUNT(&cores)));
}

std::vector<Expr> map_in_processes(const std::vector<Expr>& inputs, Expr (*f)(const Expr&)) {
  const std::size_t n = inputs.size();
  std::vector<Expr> results(n);
  std::vector<bool> done(n, false);
  const std::size_t processes = std::min(worker_processes(), n);
  if (processes > 1) {
    // the queue: the largest expressions first, in runs of `chunk`
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::vector<std::size_t> sizes(n);
    for (std::size_t i = 0; i < n; ++i) sizes[i] = expression_size(inputs[i]);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
    const std::size_t chunk = (n + kMaxTasks - 1) / kMaxTasks;
    const std::size_t tasks = (n + chunk - 1) / chunk;
    Pipe queue;
    std::vector<std::uint32_t> numbers(tasks);
    std::iota(numbers.begin(), numbers.end(), std::uint32_t{0});
    if (!write_all(queue.write, reinterpret_cast<const char*>(numbers.data()),
                   numbers.size() * sizeof(std::uint32_t))) {
      throw std::runtime_error("cannot fill the queue of a shared computation");
    }
    queue.close_write();
    // the process that takes task k computes these
    const auto each_of_task = [&](std::int64_t k, const auto& compute) {
      const std::size_t begin = std::size_t(k) * chunk, end = std::min(n, begin + chunk);
      for (std::size_t p = begin; p < end; ++p) compute(order[p]);
    };
    const SymbolTable symbols(inputs);
    Copies copies;
    std::vector<std::unique_ptr<Pipe>> answers;
    for (std::size_t c = 1; c < processes; ++c) {
      auto answer = std::make_unique<Pipe>();
      const pid_t pid = ::fork();
      if (pid < 0) break;  // no more copies: fewer hands
      if (pid == 0) {
        // a copy: each of its results as (number, 'y', hash, expression) or (number, 'n');
        // sent at the end, and out by _exit (nothing of the parent's flushed or destroyed)
        std::string bytes;
        try {
          for (std::int64_t k; (k = next_task(queue.read)) >= 0;) {
            each_of_task(k, [&](std::size_t i) {
              put(bytes, i);
              try {
                const Expr r = f(inputs[i]);
                std::string written;
                write_expression(r, symbols, written);
                bytes += 'y';
                put(bytes, r.gethash());
                bytes += written;
              } catch (...) {
                bytes += 'n';
              }
            });
          }
          write_all(answer->write, bytes.data(), bytes.size());
        } catch (...) {
        }
        ::_exit(0);
      }
      copies.pids.push_back(pid);
      answer->close_write();
      answers.push_back(std::move(answer));
    }
    // this process's share, from the same queue (what fails, computed again below in order)
    for (std::int64_t k; (k = next_task(queue.read)) >= 0;) {
      each_of_task(k, [&](std::size_t i) {
        try {
          results[i] = f(inputs[i]);
          done[i] = true;
        } catch (...) {
        }
      });
    }
    // the copies' results, each checked by its hash (a rebuilt expression unlike the sent one
    // is computed again here)
    for (std::size_t c = 0; c < answers.size(); ++c) {
      const std::string bytes = read_all(answers[c]->read);
      std::string_view rest(bytes);
      try {
        for (std::uint64_t i, hash; take(rest, i) && i < n && !rest.empty();) {
          const char status = rest.front();
          rest.remove_prefix(1);
          if (status != 'y') continue;
          if (!take(rest, hash)) break;
          const Expr r = read_expression(rest, symbols);
          if (r.gethash() != hash) continue;
          results[i] = r;
          done[i] = true;
        }
      } catch (const Untransportable&) {
        // the rest computed here
      }
    }
  }
  // what no copy gave, in order
  for (std::size_t i = 0; i < n; ++i) {
    if (!done[i]) results[i] = f(inputs[i]);
  }
  return results;
}

}  // namespace unidyn
