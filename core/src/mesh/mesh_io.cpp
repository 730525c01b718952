#include "wingspline/mesh/mesh_io.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace wingspline::mesh {

namespace {

// The text as lines of whitespace-separated tokens, comments (# to end of line) removed.
struct Line {
    int number;
    std::vector<std::string> tokens;
};

std::vector<Line> tokenize(const std::string& text) {
    std::vector<Line> lines;
    int number = 0;
    std::size_t i = 0;
    while (i <= text.size()) {
        std::size_t end = text.find('\n', i);
        if (end == std::string::npos) end = text.size();
        ++number;
        Line line{number, {}};
        std::size_t j = i;
        while (j < end) {
            const char c = text[j];
            if (c == '#') break;
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') { ++j; continue; }
            std::size_t k = j;
            while (k < end && text[k] != ' ' && text[k] != '\t' && text[k] != '\r' && text[k] != '#') ++k;
            line.tokens.push_back(text.substr(j, k - j));
            j = k;
        }
        if (!line.tokens.empty()) lines.push_back(std::move(line));
        if (end == text.size()) break;
        i = end + 1;
    }
    return lines;
}

std::string quoted(const std::string& s) { return "'" + (s.size() > 30 ? s.substr(0, 30) + "..." : s) + "'"; }

double to_number(const std::string& token, int line, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') throw ParseError("parse-error", line, "expected " + what + ", found " + quoted(token));
    return x;
}

long to_integer(const std::string& token, int line, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const long x = std::strtol(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0' || errno == ERANGE || x > 2147483647L || x < -2147483647L)
        throw ParseError("parse-error", line, "expected " + what + ", found " + quoted(token));
    return x;
}

} // namespace

IndexedMesh parse_off(const std::string& text) {
    const std::vector<Line> lines = tokenize(text);
    if (lines.empty()) throw ParseError("truncated-file", 1, "the file is empty; expected the keyword OFF");
    std::size_t at = 0;
    std::vector<std::string> header = lines[0].tokens;
    if (header[0] != "OFF") throw ParseError("parse-error", lines[0].number, "expected the keyword OFF, found " + quoted(header[0]));
    header.erase(header.begin());
    int count_line = lines[0].number;
    if (header.empty()) {
        if (lines.size() < 2) throw ParseError("truncated-file", lines[0].number + 1, "the file ends; expected the counts: vertices faces edges");
        header = lines[1].tokens;
        count_line = lines[1].number;
        at = 2;
    } else {
        at = 1;
    }
    if (header.size() < 2) throw ParseError("parse-error", count_line, "expected the counts: vertices faces edges");
    const long nv = to_integer(header[0], count_line, "the number of vertices");
    const long nf = to_integer(header[1], count_line, "the number of faces");
    if (nv < 0 || nf < 0) throw ParseError("parse-error", count_line, "the counts must not be negative");
    IndexedMesh m;
    for (long v = 0; v < nv; ++v, ++at) {
        if (at >= lines.size())
            throw ParseError("truncated-file", lines.back().number + 1, "the file ends after " + std::to_string(v) + " of " +
                             std::to_string(nv) + " vertices; expected x y z of vertex " + std::to_string(v));
        const Line& l = lines[at];
        if (l.tokens.size() < 3)
            throw ParseError("parse-error", l.number, "expected x y z of vertex " + std::to_string(v) + ", found " +
                             std::to_string(l.tokens.size()) + " number(s)");
        m.add_vertex(to_number(l.tokens[0], l.number, "the x coordinate"), to_number(l.tokens[1], l.number, "the y coordinate"),
                     to_number(l.tokens[2], l.number, "the z coordinate"));
    }
    std::vector<int32_t> corners;
    for (long f = 0; f < nf; ++f, ++at) {
        if (at >= lines.size())
            throw ParseError("truncated-file", lines.back().number + 1, "the file ends after " + std::to_string(f) + " of " +
                             std::to_string(nf) + " faces; expected face " + std::to_string(f));
        const Line& l = lines[at];
        const long n = to_integer(l.tokens[0], l.number, "the number of vertices of face " + std::to_string(f));
        if (n < 0 || static_cast<std::size_t>(n) + 1 > l.tokens.size())
            throw ParseError("parse-error", l.number, "face " + std::to_string(f) + " announces " + l.tokens[0] +
                             " vertex indices but the line has " + std::to_string(l.tokens.size() - 1));
        corners.clear();
        for (long i = 0; i < n; ++i) {
            const long v = to_integer(l.tokens[1 + i], l.number, "a vertex index");
            if (v < 0 || v >= nv)
                throw ParseError("index-out-of-range", l.number, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                 " but the file has vertices 0 to " + std::to_string(nv - 1));
            corners.push_back(static_cast<int32_t>(v));
        }
        m.add_face(corners.data(), static_cast<int32_t>(corners.size()));
    }
    if (at < lines.size())
        throw ParseError("parse-error", lines[at].number, "unexpected data after the last face, found " + quoted(lines[at].tokens[0]));
    return m;
}

IndexedMesh parse_obj(const std::string& text) {
    IndexedMesh m;
    struct PendingFace {
        int line;
        std::vector<long> refs; // 1-based or negative, as written
        long vertices_so_far;
    };
    std::vector<PendingFace> faces;
    for (const Line& l : tokenize(text)) {
        const std::string& key = l.tokens[0];
        if (key == "v") {
            if (l.tokens.size() < 4)
                throw ParseError("parse-error", l.number, "expected 'v x y z', found " + std::to_string(l.tokens.size() - 1) + " number(s)");
            m.add_vertex(to_number(l.tokens[1], l.number, "the x coordinate"), to_number(l.tokens[2], l.number, "the y coordinate"),
                         to_number(l.tokens[3], l.number, "the z coordinate"));
        } else if (key == "f") {
            PendingFace pf{l.number, {}, m.vertex_count()};
            for (std::size_t i = 1; i < l.tokens.size(); ++i) {
                const std::string& t = l.tokens[i];
                const std::string index = t.substr(0, t.find('/'));
                const long v = to_integer(index, l.number, "a vertex index (i, i/t, i//n or i/t/n)");
                if (v == 0) throw ParseError("parse-error", l.number, "OBJ vertex indices start at 1 (or count back from -1); found 0");
                pf.refs.push_back(v);
            }
            faces.push_back(std::move(pf));
        } else if (key == "vt" || key == "vn" || key == "vp" || key == "o" || key == "g" || key == "s" || key == "usemtl" ||
                   key == "mtllib") {
            continue;
        } else {
            throw ParseError("parse-error", l.number, "expected a statement v, f (or vt, vn, o, g, s, usemtl, mtllib), found " + quoted(key));
        }
    }
    const long nv = m.vertex_count();
    std::vector<int32_t> corners;
    for (const PendingFace& pf : faces) {
        corners.clear();
        for (long r : pf.refs) {
            const long v = r > 0 ? r - 1 : pf.vertices_so_far + r;
            if (v < 0 || v >= nv)
                throw ParseError("index-out-of-range", pf.line, "vertex reference " + std::to_string(r) +
                                 " points outside the " + std::to_string(nv) + " vertices of the file");
            corners.push_back(static_cast<int32_t>(v));
        }
        m.add_face(corners.data(), static_cast<int32_t>(corners.size()));
    }
    return m;
}

namespace {
void append_number(std::string& out, double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    out += buf;
}
} // namespace

std::string format_off(const IndexedMesh& m) {
    std::string out = "OFF\n" + std::to_string(m.vertex_count()) + " " + std::to_string(m.face_count()) + " 0\n";
    for (int32_t v = 0; v < m.vertex_count(); ++v) {
        for (int k = 0; k < 3; ++k) {
            if (k) out += ' ';
            append_number(out, m.positions[3 * v + k]);
        }
        out += '\n';
    }
    for (int32_t f = 0; f < m.face_count(); ++f) {
        out += std::to_string(m.face_size(f));
        for (int32_t i = 0; i < m.face_size(f); ++i) out += " " + std::to_string(m.corner(f, i));
        out += '\n';
    }
    return out;
}

std::string format_obj(const IndexedMesh& m) {
    std::string out;
    for (int32_t v = 0; v < m.vertex_count(); ++v) {
        out += "v";
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            append_number(out, m.positions[3 * v + k]);
        }
        out += '\n';
    }
    for (int32_t f = 0; f < m.face_count(); ++f) {
        out += "f";
        for (int32_t i = 0; i < m.face_size(f); ++i) out += " " + std::to_string(m.corner(f, i) + 1);
        out += '\n';
    }
    return out;
}

} // namespace wingspline::mesh
