#pragma once
// Reading the malformed-input corpus of tests/corpus/ for the native hardening
// tests. The wasm tests read the same files, so both layers check the same expectations.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hardening {

// tests/corpus/<relative>, found from this header's own path (CMake compiles with
// absolute paths), so the tests run from any working directory.
inline std::string corpus_path(const std::string& relative) {
    std::string here = __FILE__;
    const std::string tail = "tests/native/files/corpus.h";
    return here.substr(0, here.size() - tail.size()) + "tests/corpus/" + relative;
}

inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline std::vector<std::string> words(const std::string& line) {
    std::istringstream s(line);
    std::vector<std::string> out;
    for (std::string w; s >> w;) out.push_back(w);
    return out;
}

// The lines of a corpus manifest or .curve file, comments (#) and blank lines removed.
inline std::vector<std::vector<std::string>> records(const std::string& text) {
    std::vector<std::vector<std::string>> out;
    std::istringstream s(text);
    for (std::string line; std::getline(s, line);) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        auto w = words(line);
        if (!w.empty()) out.push_back(std::move(w));
    }
    return out;
}

// One line of tests/corpus/mesh/expected.txt.
struct MeshCase {
    std::string file, format, outcome, code;
    int line = 0;                    // parse-error: the 1-based line the reader must blame
    std::vector<std::string> names;  // refused / warning: words the message must contain
};

inline std::vector<MeshCase> mesh_cases() {
    std::vector<MeshCase> out;
    for (const auto& w : records(read_file(corpus_path("mesh/expected.txt")))) {
        MeshCase c;
        c.file = w.at(0);
        c.format = w.at(1);
        c.outcome = w.at(2);
        if (c.outcome != "valid") c.code = w.at(3);
        if (c.outcome == "parse-error") c.line = std::stoi(w.at(4));
        for (std::size_t i = 4; c.outcome != "parse-error" && i < w.size(); ++i) c.names.push_back(w[i]);
        out.push_back(c);
    }
    return out;
}

// A .curve file as key -> words.
inline std::map<std::string, std::vector<std::string>> curve_record(const std::string& name) {
    std::map<std::string, std::vector<std::string>> out;
    for (auto& w : records(read_file(corpus_path("curves/" + name)))) {
        const std::string key = w.front();
        out[key] = std::vector<std::string>(w.begin() + 1, w.end());
    }
    return out;
}

inline std::vector<double> numbers(const std::vector<std::string>& w) {
    std::vector<double> out;
    for (const auto& s : w) out.push_back(std::stod(s)); // reads nan and inf too
    return out;
}

} // namespace hardening
