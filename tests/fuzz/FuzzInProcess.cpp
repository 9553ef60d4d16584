// In-process fuzz driver for the readers of a case's files, built with AddressSanitizer and
// UndefinedBehaviorSanitizer (tests/fuzz/CMakeLists.txt compiles the readers' sources into it:
// a sanitizer only sees the code it compiled).
//
// Four kinds of input, each mutated from valid originals:
//   dict   the tutorials' and test cases' system/ and constant/ dictionaries, parsed with
//          Dictionary::parse (includes resolved next to the original), printed and parsed again;
//   vtp    particle files written here by writeVtp (1D, 2D, 3D, every field kind), read with
//          readVtp; a file that reads must write and read back with the same particles;
//   pvd    a particles.pvd written by PvdIndex, read, truncated, added to, written, read back;
//   state  a restart state written by Time::state(), restored into a Time (Time::restore); an
//          accepted state must leave a finite, non-negative time and a positive finite step.
// Each input must end in a result or an mfdyn::Error. Anything else is a failure: a sanitizer
// report or signal (the sanitizer's death callback), another exception, a failed round trip, a
// hang (SIGALRM after --input-timeout seconds) or memory beyond ASAN_OPTIONS' hard_rss_limit_mb /
// max_allocation_size_mb (set by fuzz.py; RLIMIT_AS cannot be used, ASan reserves terabytes of
// address space). The failing input is written to <out>/<kind>-seed<S>-iter<I>.<ext> and the
// command that reproduces it is printed.
//
// Iteration i draws from its own generator seeded with (seed, i), so "--seed S --start I
// --iterations 1" repeats exactly one input of a long run, and fuzz.py can resume after a crash.
//
//   fuzzInProcess --root <source tree> --out <dir> [--seed S] [--budget seconds] [--start I]
//                 [--iterations N] [--input-timeout seconds] [--kinds dict,vtp,pvd,state]
//   fuzzInProcess --root <source tree> --out <dir> --replay [--expect-error] <file>...
// (a replayed <file> with a <file>.expect next to it must end in an error containing its text, or
// be accepted, round trips included, when that text is "accepted"; "accepted or error" allows both)
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Time.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/PvdIndex.hpp"
#include "particles/VtpReader.hpp"
#include "particles/VtpWriter.hpp"

#include <fcntl.h>
#include <sanitizer/common_interface_defs.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// The input under test, for the death callback and the alarm handler: both may run in a signal
// handler or inside the sanitizer's runtime, so they only use write(2)/open(2) on buffers
// prepared before the input runs.

struct Current {
    const std::string* bytes = nullptr;
    char failurePath[4096] = {};
    char reproduce[8192] = {};
} current;

void writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n <= 0) return;
        data += n;
        size -= std::size_t(n);
    }
}

void writeCurrentInput() {
    if (!current.bytes) return;
    const int fd = ::open(current.failurePath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        writeAll(fd, current.bytes->data(), current.bytes->size());
        ::close(fd);
    }
    writeAll(2, current.reproduce, std::strlen(current.reproduce));
}

void onSanitizerDeath() {
    static const char head[] = "\nFUZZ FAILURE: sanitizer report or signal on this input\n";
    writeAll(2, head, sizeof head - 1);
    writeCurrentInput();
}

void onAlarm(int) {
    static const char head[] = "\nFUZZ FAILURE: hang (the input ran past --input-timeout); stack:\n";
    writeAll(2, head, sizeof head - 1);
    __sanitizer_print_stack_trace();
    writeCurrentInput();
    ::_exit(3);
}

// ---------------------------------------------------------------------------------------------
// Mutations. Generic byte edits find what nobody thought of; the structured ones aim at what the
// readers must check: numbers (sizes, counts, offsets, times) replaced by extremes, nesting and
// repetition that blow up depth or size, and the directives a dictionary can use to reach other
// files.

using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) {
    return n == 0 ? 0 : std::size_t(rng() % n);
}

const std::vector<std::string> extremeNumbers = {
    "0",
    "-1",
    "1",
    "-0",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "1e999",
    "-1e999",
    "5e-321",
    "1e-320",
    "1e-300",
    "2147483647",
    "2147483648",
    "-2147483649",
    "4294967296",
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551615",
    "18446744073709551616",
    "2305843009213693952",
    "400000000",
    "1e30",
    "0x1p+1023",
    "0x1.fffffffffffffp+1023",
    "0x1p-1074",
    "3.5",
    "",
    " ",
    "1 2",
    "\"nan\"",
    "\"0x1p+1024\"",
    "-9223372036854775808",
    "+5",
    ".5e",
    "0e",
    "1e+",
};

// The offsets of digit runs (optionally signed, with '.', 'e', 'x' and hex digits inside).
std::vector<std::pair<std::size_t, std::size_t>> numberSpans(const std::string& text, std::size_t limit) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    const std::size_t end = std::min(limit, text.size());
    for (std::size_t i = 0; i < end;) {
        if (std::isdigit(static_cast<unsigned char>(text[i]))) {
            std::size_t j = i;
            while (j < end && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '.' ||
                               text[j] == '+' || text[j] == '-'))
                ++j;
            std::size_t begin = i;
            if (begin > 0 && text[begin - 1] == '-') --begin;
            spans.emplace_back(begin, j - begin);
            i = j;
        } else {
            ++i;
        }
    }
    return spans;
}

void replaceNumber(std::string& text, Rng& rng, std::size_t limit) {
    const auto spans = numberSpans(text, limit);
    if (spans.empty()) return;
    const auto [at, len] = spans[pick(rng, spans.size())];
    text.replace(at, len, extremeNumbers[pick(rng, extremeNumbers.size())]);
}

// One generic edit somewhere in text[0, limit] (limit: the XML header of a .vtp, whose binary
// tail gets its own edits).
void genericEdit(std::string& text, Rng& rng, const std::string& alphabet, std::size_t limit) {
    limit = std::min(limit, text.size());
    const std::size_t at = pick(rng, limit + 1);
    switch (rng() % 8) {
        case 0:  // delete a span
            text.erase(at, std::min<std::size_t>(1 + rng() % 8, text.size() - at));
            break;
        case 1:  // insert a character the format gives meaning to
        case 2:
            text.insert(at, 1, alphabet[pick(rng, alphabet.size())]);
            break;
        case 3: {  // duplicate a span
            const std::size_t len = 1 + rng() % 32;
            text.insert(at, text.substr(at, len));
            break;
        }
        case 4:  // truncate
            text.resize(at);
            break;
        case 5:  // an arbitrary byte, NUL and non-ASCII included
            text.insert(at, 1, char(rng() % 256));
            break;
        case 6:  // flip a bit
            if (at < text.size()) text[at] = char(text[at] ^ (1 << (rng() % 8)));
            break;
        case 7: {  // splice: copy a span from elsewhere over this place
            const std::size_t from = pick(rng, text.size() + 1);
            const std::string span = text.substr(from, 1 + rng() % 64);
            text.replace(at, std::min(span.size(), text.size() - at), span);
            break;
        }
    }
}

// A span repeated many times: deep nesting ("{" or "<a>") and long inputs.
void repeatSpan(std::string& text, Rng& rng, const std::vector<std::string>& units, std::size_t limit) {
    const std::size_t at = pick(rng, std::min(limit, text.size()) + 1);
    const std::string& unit = units[pick(rng, units.size())];
    // Mostly modest counts, sometimes far beyond any sane depth (the readers' stack).
    const std::size_t count = rng() % 4 == 0 ? 20000 + rng() % 100000 : 1 + rng() % 300;
    std::string block;
    block.reserve(unit.size() * count);
    for (std::size_t k = 0; k < count; ++k) block += unit;
    text.insert(at, block);
}

struct Extras {
    std::vector<std::string> includeTargets;  // what a mutated #include may name
};

std::string mutateDictionary(std::string text, Rng& rng, const Extras& extras) {
    static const std::string alphabet = "{}();$#\"/*\\\n e.-+[]";
    const int edits = 1 + int(rng() % 4);
    for (int k = 0; k < edits; ++k) {
        switch (rng() % 10) {
            case 0:
            case 1:
            case 2:
            case 3:
                genericEdit(text, rng, alphabet, text.size());
                break;
            case 4:
            case 5:
                replaceNumber(text, rng, text.size());
                break;
            case 6:
                repeatSpan(text, rng, {"{", "a {", "(", "$", "#include \"\"", "x 1;"}, text.size());
                break;
            case 7: {  // a directive naming another file
                const std::string& target = extras.includeTargets[pick(rng, extras.includeTargets.size())];
                const char* directive = rng() % 2 ? "#include" : "#includeEtc";
                text.insert(pick(rng, text.size() + 1),
                            std::string("\n") + directive + " \"" + target + "\"\n");
                break;
            }
            case 8: {  // macro doubling: m1 ($m0 $m0); m2 ($m1 $m1); ... ("billion laughs")
                const int levels = 1 + int(rng() % 48);
                std::string chain = "\nm0 1;\n";
                for (int l = 1; l <= levels; ++l)
                    chain += "m" + std::to_string(l) + " ($m" + std::to_string(l - 1) + " $m" +
                             std::to_string(l - 1) + ");\n";
                text += chain;
                break;
            }
            case 9: {  // a macro reference to a key that may or may not be there
                static const std::vector<std::string> refs = {"$type", "$m0", "$../x", "$:a.b", "${a}", "$$"};
                text.insert(pick(rng, text.size() + 1), " " + refs[pick(rng, refs.size())] + " ");
                break;
            }
        }
    }
    return text;
}

// Overwrites 8 bytes of the binary tail with a little-endian integer that a reader may take for
// a byte count (the UInt64 in front of each appended array) or an id.
void overwriteWord(std::string& bytes, Rng& rng, std::size_t from) {
    if (bytes.size() < from + 8) return;
    static const std::vector<std::uint64_t> words = {0,
                                                     1,
                                                     7,
                                                     0xffffffffffffffffull,
                                                     0x8000000000000000ull,
                                                     0x7fffffffffffffffull,
                                                     1ull << 61,
                                                     1ull << 32,
                                                     0x7fffffffull,
                                                     400000000ull,
                                                     0x7ff8000000000000ull,   // a NaN's bits
                                                     0x7ff0000000000000ull};  // +inf's bits
    const std::size_t at = from + pick(rng, bytes.size() - from - 7);
    std::uint64_t w = words[pick(rng, words.size())];
    if (rng() % 4 == 0) {  // near the original value: off by one, doubled
        std::memcpy(&w, bytes.data() + at, 8);
        w = rng() % 2 ? w + 1 - 2 * (rng() % 2) : w * 2;
    }
    std::memcpy(bytes.data() + at, &w, 8);
}

// The value of a size-like attribute (NumberOfPoints, NumberOfComponents, offset, ...) set to an
// extreme: what a reader multiplies, allocates and seeks by.
void replaceSizeAttribute(std::string& bytes, Rng& rng, std::size_t header) {
    static const std::vector<std::string> names = {
        "NumberOfPoints=\"", "NumberOfVerts=\"", "NumberOfComponents=\"",
        "NumberOfTuples=\"", "offset=\"",        "header_type=\""};
    std::vector<std::size_t> starts;
    for (const std::string& name : names)
        for (std::size_t at = bytes.find(name); at != std::string::npos && at < header;
             at = bytes.find(name, at + 1))
            starts.push_back(at + name.size());
    if (starts.empty()) return;
    const std::size_t at = starts[pick(rng, starts.size())];
    const std::size_t end = bytes.find('"', at);
    if (end == std::string::npos || end >= header) return;
    bytes.replace(at, end - at, extremeNumbers[pick(rng, extremeNumbers.size())]);
}

std::string mutateXml(std::string bytes, Rng& rng, bool binaryTail) {
    static const std::string alphabet = "<>/=\"'&;#?! \n_x";
    // The header ends at the appended data's '_' marker; edits there are the XML reader's
    // business, those after it the binary reader's. Found again after every edit.
    auto headerEnd = [&bytes, binaryTail]() {
        if (!binaryTail) return bytes.size();
        const std::size_t tag = bytes.find("<AppendedData");
        const std::size_t underscore = tag == std::string::npos ? tag : bytes.find('_', tag);
        return underscore == std::string::npos ? bytes.size() : underscore + 1;
    };
    const int edits = 1 + int(rng() % 3);
    for (int k = 0; k < edits; ++k) {
        const std::size_t header = headerEnd();
        switch (rng() % 9) {
            case 0:
            case 1:
            case 2:
                genericEdit(bytes, rng, alphabet, header);
                break;
            case 3:
                replaceNumber(bytes, rng, header);
                break;
            case 4:
                replaceSizeAttribute(bytes, rng, header);
                break;
            case 5:
                repeatSpan(bytes, rng, {"<a>", "<a x=\"1\">", "<!-- c -->", "&amp;", "&#65;"}, header);
                break;
            case 6: {  // an attribute value swapped for another of its kind
                static const std::vector<std::pair<std::string, std::vector<std::string>>> swaps = {
                    {"Float64", {"Float32", "Int64", "Int32", "UInt8", "String", "Float16", ""}},
                    {"Int64", {"Float64", "Int32", "UInt64", "Int8", "String"}},
                    {"appended", {"binary", "ascii", ""}},
                    {"raw", {"base64", ""}},
                    {"LittleEndian", {"BigEndian", ""}},
                    {"UInt64", {"UInt32", "Int64", ""}},
                    {"PolyData", {"UnstructuredGrid", "Collection", ""}},
                    {"Collection", {"PolyData", ""}},
                    {"DataSet", {"DataSets", "Piece"}},
                    {"timestep", {"time", "timestep=\"1\" timestep"}},
                    {"file", {"files", "file=\"a\" file"}},
                };
                const auto& [from, tos] = swaps[pick(rng, swaps.size())];
                const std::size_t at = bytes.find(from, pick(rng, header + 1));
                if (at != std::string::npos && at < header)
                    bytes.replace(at, from.size(), tos[pick(rng, tos.size())]);
                break;
            }
            case 7:
                if (binaryTail) {
                    if (rng() % 2)
                        overwriteWord(bytes, rng, header);
                    else
                        genericEdit(bytes, rng, alphabet, bytes.size());
                } else {
                    replaceNumber(bytes, rng, header);
                }
                break;
            case 8: {  // a file entry pointing elsewhere (.pvd) or an element duplicated
                static const std::vector<std::string> names = {"../../x.vtp", "/dev/zero", "", "a\"b",
                                                               "&lt;"};
                const std::size_t at = bytes.find("file=\"", pick(rng, header + 1));
                if (at != std::string::npos && at < header) {
                    const std::size_t valueEnd = bytes.find('"', at + 6);
                    if (valueEnd != std::string::npos)
                        bytes.replace(at + 6, valueEnd - at - 6, names[pick(rng, names.size())]);
                } else {
                    genericEdit(bytes, rng, alphabet, header);
                }
                break;
            }
        }
    }
    return bytes;
}

std::string mutateState(std::string text, Rng& rng) {
    // Mostly values (the state is the solver's own file; what a bit flip or an editor does to it
    // matters most in its numbers), sometimes syntax.
    const int edits = 1 + int(rng() % 3);
    for (int k = 0; k < edits; ++k) {
        if (rng() % 3 == 0) {
            genericEdit(text, rng, "{};\"\n ", text.size());
            continue;
        }
        // Replace a whole value: between a key and its ';'.
        std::vector<std::pair<std::size_t, std::size_t>> values;
        std::istringstream lines(text);
        std::size_t offset = 0;
        for (std::string line; std::getline(lines, line); offset += line.size() + 1) {
            const std::size_t space = line.find(' ');
            const std::size_t semi = line.rfind(';');
            if (line.empty() || line[0] == '/' || space == std::string::npos || semi == std::string::npos ||
                semi < space)
                continue;
            const std::size_t start = line.find_first_not_of(' ', space);
            values.emplace_back(offset + start, semi - start);
        }
        if (values.empty()) {
            replaceNumber(text, rng, text.size());
            continue;
        }
        const auto [at, len] = values[pick(rng, values.size())];
        std::string value = extremeNumbers[pick(rng, extremeNumbers.size())];
        if (rng() % 2) value = "\"" + value + "\"";
        text.replace(at, len, value);
    }
    return text;
}

// ---------------------------------------------------------------------------------------------
// Inputs and how each kind is run.

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeBytes(const fs::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("fuzz driver: cannot write " + p.string());
}

// Files whose parent is system/ or constant/ under `dir`, skipping generated and binary ones.
void collectDictionaries(const fs::path& dir, std::vector<fs::path>& out) {
    if (!fs::is_directory(dir)) return;
    for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
        if (!it->is_regular_file()) continue;
        const fs::path& p = it->path();
        const std::string parent = p.parent_path().filename().string();
        if (parent != "system" && parent != "constant") continue;
        if (it->file_size() > 200000) continue;
        const std::string ext = p.extension().string();
        if (ext == ".stl" || ext == ".vtp" || ext == ".csv" || ext == ".png") continue;
        out.push_back(p);
    }
}

struct Outcome {
    bool accepted = false;
    std::string message;  // the error's first line when rejected
};

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string firstLine(const std::string& s) {
    return s.substr(0, std::min(s.find('\n'), std::size_t(300)));
}

class Driver {
public:
    Driver(fs::path root, fs::path out) : root_(std::move(root)), out_(std::move(out)) {
        work_ = out_ / ("work-" + std::to_string(::getpid()));
        fs::create_directories(work_ / "0.5");
        options_.etcDirectories = {root_ / "etc"};
    }
    ~Driver() {
        std::error_code ec;
        fs::remove_all(work_, ec);
    }

    void prepareCorpus() {
        collectDictionaries(root_ / "tutorials", dictionaries_);
        collectDictionaries(root_ / "tests" / "cases", dictionaries_);
        collectDictionaries(root_ / "tests" / "fuzz" / "cases", dictionaries_);
        const fs::path fixtures = root_ / "tests" / "unit" / "core" / "fixtures";
        if (fs::is_directory(fixtures))
            for (const auto& f : fs::directory_iterator(fixtures))
                if (f.path().extension() == ".dict" &&
                    readBytes(f.path()).find("expect-error") == std::string::npos)
                    dictionaries_.push_back(f.path());
        std::sort(dictionaries_.begin(), dictionaries_.end());
        for (const fs::path& p : dictionaries_) dictionaryTexts_.push_back(readBytes(p));
        if (dictionaries_.size() < 20)
            throw std::runtime_error("only " + std::to_string(dictionaries_.size()) + " dictionaries under " +
                                     root_.string() + ": is --root the source tree?");

        // Include targets: a missing file, a directory, an empty device, an endless one, a
        // FIFO nobody writes to (opening it for reading waits for a writer), a file including
        // itself, an escape from the etc directories.
        const fs::path loop = work_ / "loop.dict";
        writeBytes(loop, "a 1;\n#include \"loop.dict\"\n");
        const fs::path fifo = work_ / "fifo";
        ::mkfifo(fifo.c_str(), 0600);
        extras_.includeTargets = {"missing.dict",
                                  ".",
                                  "/dev/null",
                                  "/dev/zero",
                                  fifo.string(),
                                  loop.string(),
                                  "../../../../etc/passwd",
                                  "caseDicts/../../../../../etc/hostname",
                                  ""};

        // Particle files: every dimension and field kind the writer knows.
        for (int dim = 1; dim <= 3; ++dim) {
            const fs::path p = work_ / ("base" + std::to_string(dim) + ".vtp");
            writeParticles(p, dim);
            particleFiles_.push_back(readBytes(p));
        }

        mfdyn::PvdIndex pvd(work_ / "base.pvd");
        const char* names[] = {"0", "0.25", "0.5", "0.75", "1"};
        for (int k = 0; k <= 4; ++k) pvd.add(0.25 * k, std::string(names[k]) + "/particles.vtp");
        pvd.write();
        pvdText_ = readBytes(work_ / "base.pvd");

        controlDictPath_ = work_ / "controlDict";
        controlDictText_ =
            "startFrom latestTime; startTime 0; stopAt endTime; endTime 1; deltaT 1e-3;\n"
            "adjustTimeStep yes; maxCo 0.5; maxDeltaT 2e-3; writeControl adjustableRunTime;\n"
            "writeInterval 0.25; writePrecision 6;\n";
        writeBytes(controlDictPath_, controlDictText_);
        // A state as particleFlight leaves it at a stop at 0.5 (the exact time just above the
        // directory's name, as adjustable steps make it).
        stateText_ =
            "// Restart state of particleFlight at time 0.5 (read by startFrom latestTime)\n"
            "time               0.5;\n"
            "timeExact          \"0x1.0000000000001p-1\";\n"
            "deltaTExact        \"0x1.0624dd2f1a9fcp-9\";\n"
            "desiredDeltaTExact \"0x1.0624dd2f1a9fcp-9\";\n"
            "timeIndex          250;\n"
            "writeIndex         2;\n";
    }

    // One mutated input of `kind` from iteration generator rng; returns the bytes.
    std::string makeInput(const std::string& kind, Rng& rng, std::size_t& baseIndex) {
        if (kind == "dict") {
            baseIndex = pick(rng, dictionaries_.size());
            return mutateDictionary(dictionaryTexts_[baseIndex], rng, extras_);
        }
        if (kind == "vtp") {
            baseIndex = pick(rng, particleFiles_.size());
            return mutateXml(particleFiles_[baseIndex], rng, true);
        }
        if (kind == "pvd") return mutateXml(pvdText_, rng, false);
        return mutateState(stateText_, rng);
    }

    Outcome run(const std::string& kind, const std::string& bytes, const fs::path& dictName) {
        Outcome o;
        try {
            if (kind == "dict")
                runDictionary(bytes, dictName);
            else if (kind == "vtp")
                runParticles(bytes);
            else if (kind == "pvd")
                runPvd(bytes);
            else
                runState(bytes);
            o.accepted = true;
        } catch (const mfdyn::Error& e) {
            o.message = firstLine(e.what());
        }
        return o;
    }

    const std::vector<fs::path>& dictionaries() const { return dictionaries_; }

private:
    void runDictionary(const std::string& text, const fs::path& name) {
        const mfdyn::Dictionary d = mfdyn::Dictionary::parse(text, name.string(), options_);
        const std::string printed = d.str();
        // What the parser accepted, printed, must parse again (mfDictionary rewrites files so).
        try {
            mfdyn::Dictionary::parse(printed, name.string() + " (printed)", options_);
        } catch (const mfdyn::Error& e) {
            throw Failure("an accepted dictionary printed as text that does not parse: " +
                          firstLine(e.what()));
        }
    }

    void runParticles(const std::string& bytes) {
        const fs::path in = work_ / "particles.vtp";
        writeBytes(in, bytes);
        const mfdyn::ParticleFile file = mfdyn::readVtp(in);
        if (!file.particles) throw Failure("readVtp returned no particles and no error");
        // What was read must write and read back the same: a restart reads what the run wrote.
        const fs::path again = work_ / "again.vtp";
        try {
            mfdyn::writeVtp(again, *file.particles, file.time);
        } catch (const mfdyn::Error& e) {
            throw Failure("particles read from this file cannot be written back: " + firstLine(e.what()));
        }
        mfdyn::ParticleFile back;
        try {
            back = mfdyn::readVtp(again);
        } catch (const mfdyn::Error& e) {
            throw Failure("particles read from this file, written back, do not read: " + firstLine(e.what()));
        }
        if (back.particles->size() != file.particles->size() ||
            back.particles->dimension() != file.particles->dimension() ||
            back.particles->fieldNames() != file.particles->fieldNames())
            throw Failure("particles read from this file read back different after writing (" +
                          std::to_string(file.particles->size()) + " -> " +
                          std::to_string(back.particles->size()) + " particles)");
    }

    void runPvd(const std::string& bytes) {
        const fs::path in = work_ / "particles.pvd";
        writeBytes(in, bytes);
        mfdyn::PvdIndex index = mfdyn::PvdIndex::read(in);
        index.truncateAfter(0.6);
        index.add(0.75, "0.75/particles.vtp");
        index.write();
        const mfdyn::PvdIndex back = mfdyn::PvdIndex::read(in);
        if (back.entries().size() != index.entries().size())
            throw Failure("particles.pvd written from this index reads back with " +
                          std::to_string(back.entries().size()) + " entries instead of " +
                          std::to_string(index.entries().size()));
        for (std::size_t k = 0; k < back.entries().size(); ++k)
            if (back.entries()[k].time != index.entries()[k].time ||
                back.entries()[k].file != index.entries()[k].file)
                throw Failure("particles.pvd entry " + std::to_string(k) +
                              " reads back different after writing");
    }

    void runState(const std::string& text) {
        const fs::path name = work_ / "0.5" / "state";
        writeBytes(name, text);
        const mfdyn::Dictionary control =
            mfdyn::Dictionary::parse(controlDictText_, controlDictPath_.string());
        mfdyn::Time time(controlDictPath_, control);
        time.start(0.5, "0.5");
        const mfdyn::Dictionary state = mfdyn::Dictionary::read(name);
        time.restore(state);
        // A state that restores must leave a time the run can go on from (issue 14: a state with
        // timeExact "nan" ran at t = nan and wrote a directory named nan).
        if (!std::isfinite(time.value()) || time.value() < 0 || !std::isfinite(time.deltaT()) ||
            !(time.deltaT() > 0) || time.timeIndex() < 0)
            throw Failure("the state restored to t = " + std::to_string(time.value()) +
                          ", dt = " + std::to_string(time.deltaT()) + ", step " +
                          std::to_string(time.timeIndex()) + " without an error");
    }

    static void writeParticles(const fs::path& file, int dim) {
        const std::size_t n = 6;
        auto fill = [n](auto& particles) {
            using Set = std::decay_t<decltype(particles)>;
            constexpr int D = Set::dim;
            auto& x = particles.position();
            auto& v = particles.vectorField("velocity");
            auto& rho = particles.scalarField("density");
            auto& stress = particles.symmTensorField("stress");
            auto& grad = particles.tensorField("velocityGradient");
            auto& region = particles.region();
            auto& id = particles.globalId();
            for (std::size_t i = 0; i < n; ++i) {
                for (int c = 0; c < D; ++c) x[i][c] = 0.1 * double(i) + c;
                v[i].setConstant(double(i));
                rho[i] = 1000.0 + double(i);
                stress[i].c.fill(-1.0 * double(i));
                grad[i].setIdentity();
                region[i] = std::int64_t(i % 2);
                id[i] = std::int64_t(i);
            }
            particles.regionNames = {"left", "right"};
            particles.materialNames = {"steel"};
        };
        if (dim == 1) {
            mfdyn::ParticleSet<1> p(n);
            fill(p);
            mfdyn::writeVtp(file, p, 0.5);
        } else if (dim == 2) {
            mfdyn::ParticleSet<2> p(n);
            fill(p);
            mfdyn::writeVtp(file, p, 0.5);
        } else {
            mfdyn::ParticleSet<3> p(n);
            fill(p);
            mfdyn::writeVtp(file, p, 0.5);
        }
    }

    fs::path root_, out_, work_;
    mfdyn::ReadOptions options_;
    std::vector<fs::path> dictionaries_;
    std::vector<std::string> dictionaryTexts_;
    Extras extras_;
    std::vector<std::string> particleFiles_;
    std::string pvdText_, stateText_, controlDictText_;
    fs::path controlDictPath_;
};

const std::map<std::string, std::string> extensionOf = {
    {"dict", ".dict"}, {"vtp", ".vtp"}, {"pvd", ".pvd"}, {"state", ".state"}};

std::string kindOfFile(const fs::path& p) {
    for (const auto& [kind, ext] : extensionOf)
        if (p.extension() == ext) return kind;
    return {};
}

struct Options {
    fs::path root, out;
    std::uint64_t seed = 14;
    double budget = 30;
    long long start = 0, iterations = -1;
    unsigned inputTimeout = 20;
    std::vector<std::string> kinds = {"dict", "vtp", "pvd", "state"};
    bool replay = false, expectError = false;
    std::vector<fs::path> files;
};

[[noreturn]] void usage(const std::string& why) {
    std::cerr
        << "fuzzInProcess: " << why
        << "\nusage: fuzzInProcess --root <source tree> --out <dir> [--seed S] [--budget seconds]\n"
           "                     [--start I] [--iterations N] [--input-timeout seconds]\n"
           "                     [--kinds dict,vtp,pvd,state]\n"
           "       fuzzInProcess --root <source tree> --out <dir> --replay [--expect-error] <file>...\n";
    std::exit(64);
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--root")
            o.root = value();
        else if (a == "--out")
            o.out = value();
        else if (a == "--seed")
            o.seed = std::stoull(value());
        else if (a == "--budget")
            o.budget = std::stod(value());
        else if (a == "--start")
            o.start = std::stoll(value());
        else if (a == "--iterations")
            o.iterations = std::stoll(value());
        else if (a == "--input-timeout")
            o.inputTimeout = unsigned(std::stoul(value()));
        else if (a == "--kinds") {
            o.kinds.clear();
            std::stringstream s(value());
            for (std::string k; std::getline(s, k, ',');) {
                if (!extensionOf.count(k)) usage("unknown kind '" + k + "' (dict, vtp, pvd, state)");
                o.kinds.push_back(k);
            }
        } else if (a == "--replay")
            o.replay = true;
        else if (a == "--expect-error")
            o.expectError = true;
        else if (!a.empty() && a[0] == '-')
            usage("unknown option " + a);
        else
            o.files.emplace_back(a);
    }
    if (o.root.empty() || o.out.empty()) usage("--root and --out are required");
    if (o.kinds.empty()) usage("--kinds is empty");
    return o;
}

// Arms the failure path and message for one input before it runs.
void arm(const std::string& bytes, const fs::path& failureFile, const std::string& reproduce) {
    current.bytes = &bytes;
    std::snprintf(current.failurePath, sizeof current.failurePath, "%s", failureFile.c_str());
    std::snprintf(current.reproduce, sizeof current.reproduce, "%s", reproduce.c_str());
}

void disarm() {
    current.bytes = nullptr;
}

int replay(Driver& driver, const Options& o) {
    int bad = 0;
    for (const fs::path& file : o.files) {
        const std::string kind = kindOfFile(file);
        if (kind.empty()) usage("cannot tell the kind of " + file.string() + " (.dict, .vtp, .pvd, .state)");
        const std::string bytes = readBytes(file);
        const fs::path copy = o.out / ("replayed-" + file.filename().string());
        arm(bytes, copy, "  input: " + file.string() + "\n");
        ::alarm(o.inputTimeout);
        try {
            // A fixture dictionary is parsed where it lies, so its includes resolve next to it.
            const Outcome r = driver.run(kind, bytes, fs::absolute(file));
            ::alarm(0);
            // <fixture>.expect, when there, holds words the error must contain (what the
            // fixed reader says about this input), "accepted" for a valid input, or "accepted or
            // error" where either is right.
            const fs::path expectFile = file.string() + ".expect";
            std::string expected = fs::exists(expectFile) ? readBytes(expectFile) : std::string();
            while (!expected.empty() && (expected.back() == '\n' || expected.back() == ' '))
                expected.pop_back();
            if (expected == "accepted or error") {
                // Either answer is right (a choice the reader's owner makes); a failed round trip,
                // a crash or another exception is not.
                std::cout << "ok   " << file.filename().string() << ": "
                          << (r.accepted ? "accepted" : "error: " + r.message) << "\n";
            } else if (expected == "accepted") {
                // A valid input that once failed a round trip: it must be read, and round-trip.
                if (!r.accepted) {
                    std::cout << "FAIL " << file.string() << ": must be accepted (" << expectFile.string()
                              << "), but: " << r.message << "\n";
                    ++bad;
                } else {
                    std::cout << "ok   " << file.filename().string() << ": accepted, as it must be\n";
                }
            } else if (r.accepted && o.expectError) {
                std::cout << "FAIL " << file.string() << ": accepted, a fixture must end in an error\n";
                ++bad;
            } else if (!r.accepted && r.message.find(expected) == std::string::npos) {
                std::cout << "FAIL " << file.string() << ": the error '" << r.message << "' does not say '"
                          << expected << "' (" << expectFile.string() << ")\n";
                ++bad;
            } else {
                std::cout << "ok   " << file.filename().string() << ": "
                          << (r.accepted ? "accepted" : "error: " + r.message) << "\n";
            }
        } catch (const std::exception& e) {
            ::alarm(0);
            std::cout << "FAIL " << file.string() << ": " << e.what() << "\n";
            ++bad;
        }
        disarm();
    }
    return bad ? 2 : 0;
}

int fuzz(Driver& driver, const Options& o, const std::string& self) {
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    std::map<std::string, std::pair<long long, long long>> counts;  // kind -> accepted, rejected
    long long done = 0;
    std::cout << "fuzzInProcess: seed " << o.seed << ", budget " << o.budget << " s, from iteration "
              << o.start << ", " << driver.dictionaries().size() << " dictionaries in the corpus"
              << std::endl;
    for (long long i = o.start;; ++i) {
        const double elapsed = std::chrono::duration<double>(Clock::now() - begin).count();
        if (o.iterations >= 0 ? done >= o.iterations : elapsed >= o.budget) break;
        std::seed_seq seq{std::uint32_t(o.seed), std::uint32_t(o.seed >> 32), std::uint32_t(i),
                          std::uint32_t(std::uint64_t(i) >> 32)};
        Rng rng(seq);
        const std::string kind = o.kinds[pick(rng, o.kinds.size())];
        std::size_t base = 0;
        const std::string bytes = driver.makeInput(kind, rng, base);
        const fs::path dictName = kind == "dict" ? driver.dictionaries()[base] : fs::path();
        const fs::path failure = o.out / (kind + "-seed" + std::to_string(o.seed) + "-iter" +
                                          std::to_string(i) + extensionOf.at(kind));
        std::ostringstream how;
        how << "  kind " << kind << (kind == "dict" ? ", mutated from " + dictName.string() : std::string())
            << "\n  input written to " << failure.string() << "\n  reproduce: " << self << " --root "
            << o.root.string() << " --out " << o.out.string() << " --seed " << o.seed << " --start " << i
            << " --iterations 1 --kinds " << kind << "\n"
            << "  or replay:  " << self << " --root " << o.root.string() << " --out " << o.out.string()
            << " --replay " << failure.string() << "\nFUZZ FAILED AT ITERATION " << i << "\n";
        // The replay of a dictionary resolves includes next to the replayed file, so the one kept
        // must be parsed under its original name to reproduce; the seed form always does.
        arm(bytes, failure, how.str());
        ::alarm(o.inputTimeout);
        try {
            const Outcome r = driver.run(kind, bytes, dictName);
            (r.accepted ? counts[kind].first : counts[kind].second)++;
        } catch (const std::exception& e) {
            ::alarm(0);
            std::cerr << "\nFUZZ FAILURE: "
                      << (dynamic_cast<const Failure*>(&e) ? ""
                                                           : "an exception other than "
                                                             "mfdyn::Error: ")
                      << e.what() << "\n";
            writeCurrentInput();
            return 2;
        }
        ::alarm(0);
        disarm();
        ++done;
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - begin).count();
    std::cout << "fuzzInProcess: " << done << " inputs in " << elapsed << " s ("
              << (elapsed > 0 ? done / elapsed : 0) << " per second), iterations " << o.start << ".."
              << o.start + done - 1 << "; accepted/rejected:";
    for (const auto& [kind, c] : counts) std::cout << " " << kind << " " << c.first << "/" << c.second;
    std::cout << std::endl;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    fs::create_directories(o.out);
    __sanitizer_set_death_callback(onSanitizerDeath);
    std::signal(SIGALRM, onAlarm);
    try {
        Driver driver(o.root, o.out);
        driver.prepareCorpus();
        return o.replay ? replay(driver, o) : fuzz(driver, o, argv[0]);
    } catch (const std::exception& e) {
        // Preparing the corpus uses only valid inputs: an error here is the harness's own.
        std::cerr << "fuzzInProcess: cannot prepare the corpus: " << e.what() << "\n";
        return 64;
    }
}
