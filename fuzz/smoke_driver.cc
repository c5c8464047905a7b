// The fuzz targets without libFuzzer, for the ordinary build's test suite: every seed of the
// target's corpus goes through LLVMFuzzerTestOneInput, then a fixed number of seeded mutations
// of them (bit flips, boundary bytes, inserted, erased and repeated runs, splices of two seeds).
// Same seed and run count, same inputs. A crash leaves the input that caused it in the working
// directory (smoke-crash-<pid>) before the signal ends the process, so ctest reports a failure
// that can be replayed with the libFuzzer build (scripts/fuzz). No sanitizers here: the
// sanitized, coverage-guided runs are scripts/fuzz's.

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

using Bytes = std::vector<uint8_t>;

constexpr size_t kMaxInput = 1 << 16;

// The input being run, for the crash handler (written with write(2) only).
const Bytes* current_input = nullptr;

void SaveInputAndDie(int signal_number) {
  char name[64];
  std::snprintf(name, sizeof name, "smoke-crash-%d", static_cast<int>(getpid()));
  const int fd = ::open(name, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0 && current_input != nullptr) {
    const ssize_t ignored = ::write(fd, current_input->data(), current_input->size());
    (void)ignored;
    ::close(fd);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void Run(const Bytes& input) {
  current_input = &input;
  LLVMFuzzerTestOneInput(input.data(), input.size());
  current_input = nullptr;
}

uint64_t Below(std::mt19937_64& rng, uint64_t n) { return n == 0 ? 0 : rng() % n; }

void Mutate(Bytes& b, const std::vector<Bytes>& seeds, std::mt19937_64& rng) {
  static constexpr uint8_t kBoundary[] = {0x00, 0x01, 0x7f, 0x80, 0xff, 0xfe, '-', '9', '\n'};
  switch (Below(rng, 6)) {
    case 0:  // flip a bit
      if (!b.empty()) b[Below(rng, b.size())] ^= static_cast<uint8_t>(1u << Below(rng, 8));
      break;
    case 1:  // a boundary byte
      if (!b.empty()) b[Below(rng, b.size())] = kBoundary[Below(rng, std::size(kBoundary))];
      break;
    case 2: {  // insert random bytes
      const size_t at = Below(rng, b.size() + 1);
      Bytes run(1 + Below(rng, 8));
      for (uint8_t& v : run) v = static_cast<uint8_t>(rng());
      b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), run.begin(), run.end());
      break;
    }
    case 3: {  // erase a run
      if (b.empty()) break;
      const size_t at = Below(rng, b.size());
      const size_t n = 1 + Below(rng, std::min<size_t>(16, b.size() - at));
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(at),
              b.begin() + static_cast<std::ptrdiff_t>(at + n));
      break;
    }
    case 4: {  // repeat a run
      if (b.empty()) break;
      const size_t at = Below(rng, b.size());
      const size_t n = 1 + Below(rng, std::min<size_t>(32, b.size() - at));
      const Bytes run(b.begin() + static_cast<std::ptrdiff_t>(at),
                      b.begin() + static_cast<std::ptrdiff_t>(at + n));
      b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), run.begin(), run.end());
      break;
    }
    default: {  // splice: this input's head, another seed's tail
      const Bytes& other = seeds[Below(rng, seeds.size())];
      const size_t head = Below(rng, b.size() + 1);
      const size_t tail = Below(rng, other.size() + 1);
      b.resize(head);
      b.insert(b.end(), other.begin() + static_cast<std::ptrdiff_t>(tail), other.end());
      break;
    }
  }
  if (b.size() > kMaxInput) b.resize(kMaxInput);
}

int Usage(const char* self) {
  std::fprintf(
      stderr,
      "usage: %s CORPUS_DIR [--runs N] [--seed S]  (a missing CORPUS_DIR starts from nothing)\n",
      self);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return Usage(argv[0]);
  long runs = 2000;
  uint64_t seed = 1;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--runs") == 0) {
      runs = std::strtol(argv[i + 1], nullptr, 10);
    } else if (std::strcmp(argv[i], "--seed") == 0) {
      seed = std::strtoull(argv[i + 1], nullptr, 10);
    } else {
      return Usage(argv[0]);
    }
  }
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1], error)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  if (error) {
    std::fprintf(stderr, "%s: cannot read the corpus %s: %s\n", argv[0], argv[1],
                 error.message().c_str());
    return 2;
  }
  std::sort(files.begin(), files.end());  // directory order is not deterministic
  std::vector<Bytes> seeds;
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    seeds.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (seeds.empty()) seeds.emplace_back();  // no corpus yet: mutations of the empty input
  for (const int s : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(s, SaveInputAndDie);

  const auto start = std::chrono::steady_clock::now();
  for (const Bytes& s : seeds) Run(s);
  std::mt19937_64 rng(seed);
  for (long r = 0; r < runs; ++r) {
    Bytes input = seeds[Below(rng, seeds.size())];
    for (uint64_t m = 0, n = 1 + Below(rng, 4); m < n; ++m) Mutate(input, seeds, rng);
    Run(input);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %zu seeds and %ld mutations in %.2f s, no crash\n",
              std::filesystem::path(argv[0]).filename().c_str(), seeds.size(), runs, seconds);
  return 0;
}
