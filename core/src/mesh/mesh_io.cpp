#include "wingspline/mesh/mesh_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace wingspline::mesh {

namespace {

// The text one line at a time, as whitespace-separated tokens with comments (# to the end
// of the line) removed. Tokens are views into the text (or into the current piece of a
// streamed text): nothing is copied per number (a 61 MB OFF used to take 435 MB of wasm
// memory in tokens). Lines end at LF, CRLF or a lone CR; a UTF-8 byte-order mark at the
// very start is skipped (editors write both).
//
// Streamed (a TextSource), the reader holds one piece plus the unfinished line carried
// over: a file is read in bounded memory and a file over the limits is refused before the
// rest of it is ever copied (an over-limit 55 MB file grew the wasm memory).
class LineReader {
public:
    explicit LineReader(std::string_view text) : text_(text), at_end_(true) { skip_bom(); }
    explicit LineReader(const TextSource& source) : source_(&source) {
        do refill(); while (text_.size() < 3 && !at_end_); // enough to see a byte-order mark
        skip_bom();
    }

    // Moves to the next line that has tokens; false at the end of the text.
    bool next() {
        for (;;) {
            if (pos_ >= text_.size()) {
                if (at_end_) break;
                refill();
                continue;
            }
            std::size_t end = pos_;
            while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
            if (end - pos_ > kMaxLine)
                throw ParseError("line-too-long", number_ + 1, "the line is longer than " + std::to_string(kMaxLine) +
                                 " characters; no line of a mesh file needs that many");
            if (end == text_.size() && !at_end_) {
                refill(); // the line goes on in the next piece
                continue;
            }
            ++number_;
            tokens_.clear();
            for (std::size_t j = pos_; j < end;) {
                const char c = text_[j];
                if (c == '#') break;
                if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
                    ++j;
                    continue;
                }
                std::size_t k = j;
                while (k < end && text_[k] != ' ' && text_[k] != '\t' && text_[k] != '\f' && text_[k] != '\v' && text_[k] != '#') ++k;
                tokens_.push_back(text_.substr(j, k - j));
                j = k;
            }
            // LF, CRLF and a lone CR (old Mac files) each end one line.
            if (end == text_.size()) {
                pos_ = end;
            } else if (text_[end] == '\n') {
                pos_ = end + 1;
            } else if (end + 1 < text_.size()) {
                pos_ = end + (text_[end + 1] == '\n' ? 2 : 1);
            } else {
                // A CR ending this piece: its LF may open the next one (skipped on refill;
                // the tokens are views into this piece, so the refill waits for next()).
                pos_ = end + 1;
                pending_cr_ = !at_end_;
            }
            if (!tokens_.empty()) {
                last_with_tokens_ = number_;
                return true;
            }
        }
        tokens_.clear();
        return false;
    }
    int number() const { return number_; }
    const std::vector<std::string_view>& tokens() const { return tokens_; }
    // The line a "the file ends" message blames: the one after the last line with tokens.
    int line_after_last() const { return last_with_tokens_ + 1; }

private:
    static constexpr std::size_t kPiece = 64 * 1024;
    static constexpr std::size_t kMaxLine = 1 << 20;

    void skip_bom() {
        if (text_.substr(pos_, 3) == "\xEF\xBB\xBF") pos_ += 3;
    }
    // Keeps the unfinished line [pos_, end of piece) and appends the next piece.
    void refill() {
        const std::size_t keep = pos_ < text_.size() ? text_.size() - pos_ : 0;
        buffer_.erase(0, buffer_.size() - keep);
        const std::size_t old = buffer_.size();
        buffer_.resize(old + kPiece);
        const std::size_t got = (*source_)(&buffer_[old], kPiece, offset_);
        offset_ += got;
        buffer_.resize(old + got);
        if (got == 0) at_end_ = true;
        text_ = buffer_;
        pos_ = pending_cr_ && keep == 0 && !buffer_.empty() && buffer_[0] == '\n' ? 1 : 0;
        pending_cr_ = false;
    }

    const TextSource* source_ = nullptr;
    std::size_t offset_ = 0;
    std::string buffer_;
    std::string_view text_;
    std::size_t pos_ = 0;
    bool at_end_ = false;
    bool pending_cr_ = false;
    int number_ = 0;
    int last_with_tokens_ = 0;
    std::vector<std::string_view> tokens_;
};

std::string quoted(std::string_view s) {
    return "'" + (s.size() > 30 ? std::string(s.substr(0, 30)) + "..." : std::string(s)) + "'";
}

// strtod/strtol need a terminated string: short tokens are copied to the stack.
template <class T> struct Parsed {
    T value;
    bool whole;       // the token was one number, nothing else
    bool out_of_range; // errno == ERANGE
};

template <class Parse> auto parse_token(std::string_view token, Parse&& parse) {
    char small[64];
    std::string large;
    const char* begin;
    if (token.size() < sizeof small) {
        token.copy(small, token.size());
        small[token.size()] = '\0';
        begin = small;
    } else {
        large.assign(token);
        begin = large.c_str();
    }
    char* end = nullptr;
    errno = 0;
    const auto x = parse(begin, &end);
    const bool out_of_range = errno == ERANGE;
    return Parsed<decltype(x)>{x, end != begin && end == begin + token.size(), out_of_range};
}

double to_number(std::string_view token, int line, const char* what) {
    // Overflow (1e999) reads as an infinity, which validation then names; only text that
    // is not one number is a parse error here.
    const auto p = parse_token(token, [](const char* b, char** e) { return std::strtod(b, e); });
    if (!p.whole) throw ParseError("parse-error", line, std::string("expected ") + what + ", found " + quoted(token));
    return p.value;
}

// `what` names the expected number: a string literal, or a function that builds the
// name only when it is needed (a message per face would cost an allocation per face).
template <class What> long to_integer(std::string_view token, int line, What&& what) {
    const auto p = parse_token(token, [](const char* b, char** e) { return std::strtol(b, e, 10); });
    if (!p.whole || p.out_of_range || p.value > 2147483647L || p.value < -2147483647L) {
        std::string name;
        if constexpr (std::is_invocable_v<What>) name = what(); else name = what;
        throw ParseError("parse-error", line, "expected " + name + ", found " + quoted(token));
    }
    return p.value;
}

// A coordinate of a vertex line, refused at its line when finite but beyond the bound.
double to_coordinate(std::string_view token, int line, const char* what, const MeshLimits& limits) {
    const double x = to_number(token, line, what);
    if (std::isfinite(x) && std::abs(x) > limits.max_coordinate) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "%g", limits.max_coordinate);
        throw ParseError("coordinate-out-of-range", line, std::string(what) + " " + std::string(token.substr(0, 30)) +
                         " is beyond the limit of " + buf + " in size");
    }
    return x;
}

void check_corners(long n, long face, int line) {
    if (n > kMaxFaceCorners) throw ParseError("face-too-large", line, face_too_large_message(static_cast<int32_t>(face), n));
}

std::string too_many(long n, const char* what, long limit) {
    return "the file has " + std::to_string(n) + " " + what + "; a mesh file may have at most " + std::to_string(limit);
}

std::string face_name(long f) { return face_label(static_cast<int32_t>(f)); }
// The vertex of an OFF vertex line: its label, and the number the face lines call it by.
std::string vertex_name(long v) { return vertex_label(static_cast<int32_t>(v)) + " (called " + std::to_string(v) + " in the face lines)"; }
std::string file_vertices(long n) { return "the file has " + elements_text(&vertex_label, "vertices", static_cast<int32_t>(n)); }


IndexedMesh read_off(LineReader& in, std::size_t text_size, const MeshLimits& limits) {
    if (!in.next()) throw ParseError("truncated-file", 1, "the file is empty; expected the keyword OFF");
    if (in.tokens()[0] != "OFF") throw ParseError("parse-error", in.number(), "expected the keyword OFF, found " + quoted(in.tokens()[0]));
    std::vector<std::string_view> header(in.tokens().begin() + 1, in.tokens().end());
    if (header.empty()) {
        if (!in.next()) throw ParseError("truncated-file", in.line_after_last(), "the file ends; expected the counts: vertices faces edges");
        header = in.tokens();
    }
    const int count_line = in.number();
    if (header.size() < 2) throw ParseError("parse-error", count_line, "expected the counts: vertices faces edges");
    const long nv = to_integer(header[0], count_line, "the number of vertices");
    const long nf = to_integer(header[1], count_line, "the number of faces");
    if (nv < 0 || nf < 0) throw ParseError("parse-error", count_line, "the counts must not be negative");
    // Refused from the header, before anything is reserved or read.
    if (nv > limits.max_vertices) throw ParseError("too-large", count_line, too_many(nv, "vertices", limits.max_vertices));
    if (nf > limits.max_faces) throw ParseError("too-large", count_line, too_many(nf, "faces", limits.max_faces));
    // Room for what the header announces, but never more than the text can hold (a vertex
    // line has at least 6 bytes, "0 0 0\n", a face line 8), so a false header cannot ask
    // for gigabytes.
    IndexedMesh m;
    const std::size_t vertices = std::min<std::size_t>(static_cast<std::size_t>(nv), text_size / 6 + 1);
    const std::size_t faces = std::min<std::size_t>(static_cast<std::size_t>(nf), text_size / 8 + 1);
    m.positions.reserve(3 * vertices);
    m.face_offsets.reserve(faces + 1);
    m.face_vertices.reserve(3 * faces);
    for (long v = 0; v < nv; ++v) {
        if (!in.next())
            throw ParseError("truncated-file", in.line_after_last(), "the file ends after " + std::to_string(v) + " of " +
                             std::to_string(nv) + " vertices; expected x y z of " + vertex_name(v));
        const auto& t = in.tokens();
        if (t.size() < 3)
            throw ParseError("parse-error", in.number(), "expected x y z of " + vertex_name(v) + ", found " +
                             std::to_string(t.size()) + " number(s)");
        const double x = to_coordinate(t[0], in.number(), "the x coordinate", limits);
        const double y = to_coordinate(t[1], in.number(), "the y coordinate", limits);
        const double z = to_coordinate(t[2], in.number(), "the z coordinate", limits);
        m.add_vertex(x, y, z);
    }
    std::vector<int32_t> corners;
    for (long f = 0; f < nf; ++f) {
        if (!in.next())
            throw ParseError("truncated-file", in.line_after_last(), "the file ends after " + std::to_string(f) + " of " +
                             std::to_string(nf) + " faces; expected " + face_name(f));
        const auto& t = in.tokens();
        const long n = to_integer(t[0], in.number(), [f] { return "the number of vertices of " + face_name(f); });
        if (n < 0 || static_cast<std::size_t>(n) + 1 > t.size())
            throw ParseError("parse-error", in.number(), face_name(f) + " announces " + std::string(t[0]) +
                             " vertex indices but the line has " + std::to_string(t.size() - 1));
        check_corners(n, f, in.number());
        corners.clear();
        for (long i = 0; i < n; ++i) {
            const long v = to_integer(t[1 + i], in.number(), "a vertex index");
            if (v < 0 || v >= nv)
                throw ParseError("index-out-of-range", in.number(), face_name(f) + " refers to vertex " + std::to_string(v) +
                                 (v >= 0 ? ", that is " + vertex_label(static_cast<int32_t>(v)) + " (an OFF file counts its vertices from 0)" : "") +
                                 ", but " + file_vertices(nv));
            corners.push_back(static_cast<int32_t>(v));
        }
        m.add_face(corners.data(), static_cast<int32_t>(corners.size()));
    }
    if (in.next()) throw ParseError("parse-error", in.number(), "unexpected data after the last face, found " + quoted(in.tokens()[0]));
    return m;
}

// The OBJ limits checked by a first pass that stores nothing (OBJ has no header), so a
// file over them is refused before anything grows.
void prescan_obj(LineReader& in, const MeshLimits& limits) {
    long vertices = 0, faces = 0;
    while (in.next()) {
        const std::string_view key = in.tokens()[0];
        if (key == "v" && ++vertices > limits.max_vertices)
            throw ParseError("too-large", in.number(), too_many(vertices, "vertices or more", limits.max_vertices));
        if (key == "f") {
            if (++faces > limits.max_faces) throw ParseError("too-large", in.number(), too_many(faces, "faces or more", limits.max_faces));
            check_corners(static_cast<long>(in.tokens().size()) - 1, faces - 1, in.number());
        }
    }
}

IndexedMesh read_obj(LineReader& in, const MeshLimits& limits) {
    IndexedMesh m;
    // Face references as written (1-based, or negative = relative to the vertices read so
    // far), resolved once every vertex is known; flat arrays, one entry per face or corner.
    std::vector<long> refs;
    std::vector<int32_t> ref_offsets{0}, face_lines;
    std::vector<long> vertices_before;
    while (in.next()) {
        const auto& t = in.tokens();
        const std::string_view key = t[0];
        if (key == "v") {
            if (t.size() < 4)
                throw ParseError("parse-error", in.number(), "expected 'v x y z', found " + std::to_string(t.size() - 1) + " number(s)");
            if (m.vertex_count() >= limits.max_vertices)
                throw ParseError("too-large", in.number(), too_many(static_cast<long>(m.vertex_count()) + 1, "vertices or more", limits.max_vertices));
            const double x = to_coordinate(t[1], in.number(), "the x coordinate", limits);
            const double y = to_coordinate(t[2], in.number(), "the y coordinate", limits);
            const double z = to_coordinate(t[3], in.number(), "the z coordinate", limits);
            m.add_vertex(x, y, z);
        } else if (key == "f") {
            if (face_lines.size() >= static_cast<std::size_t>(limits.max_faces))
                throw ParseError("too-large", in.number(), too_many(static_cast<long>(face_lines.size()) + 1, "faces or more", limits.max_faces));
            check_corners(static_cast<long>(t.size()) - 1, static_cast<long>(face_lines.size()), in.number());
            for (std::size_t i = 1; i < t.size(); ++i) {
                const std::string_view index = t[i].substr(0, t[i].find('/'));
                const long v = to_integer(index, in.number(), "a vertex index (i, i/t, i//n or i/t/n)");
                if (v == 0) throw ParseError("parse-error", in.number(), "OBJ vertex indices start at 1 (or count back from -1); found 0");
                refs.push_back(v);
            }
            ref_offsets.push_back(static_cast<int32_t>(refs.size()));
            face_lines.push_back(in.number());
            vertices_before.push_back(m.vertex_count());
        } else if (key == "vt" || key == "vn" || key == "vp" || key == "o" || key == "g" || key == "s" || key == "usemtl" ||
                   key == "mtllib") {
            continue;
        } else {
            throw ParseError("parse-error", in.number(), "expected a statement v, f (or vt, vn, o, g, s, usemtl, mtllib), found " + quoted(key));
        }
    }
    const long nv = m.vertex_count();
    std::vector<int32_t> corners;
    for (std::size_t f = 0; f < face_lines.size(); ++f) {
        corners.clear();
        for (int32_t i = ref_offsets[f]; i < ref_offsets[f + 1]; ++i) {
            const long r = refs[i];
            const long v = r > 0 ? r - 1 : vertices_before[f] + r;
            if (v < 0 || v >= nv)
                throw ParseError("index-out-of-range", face_lines[f], face_name(static_cast<long>(f)) + " refers to " +
                                 (r > 0 ? vertex_label(static_cast<int32_t>(r - 1))
                                        : "vertex " + std::to_string(r) + ", counting back from " +
                                              (vertices_before[f] > 0 ? vertex_label(static_cast<int32_t>(vertices_before[f] - 1)) + " (the last vertex before it)"
                                                                      : std::string("no vertex (none comes before it)"))) +
                                 ", but " + file_vertices(nv));
            corners.push_back(static_cast<int32_t>(v));
        }
        m.add_face(corners.data(), static_cast<int32_t>(corners.size()));
    }
    return m;
}

} // namespace

IndexedMesh parse_off(std::string_view text, const MeshLimits& limits) {
    LineReader in(text);
    return read_off(in, text.size(), limits);
}

IndexedMesh parse_off(const TextSource& source, const MeshLimits& limits) {
    LineReader in(source);
    // Reservations are capped by the header and the limits alone (the size is not known).
    return read_off(in, 8 * static_cast<std::size_t>(std::max(limits.max_vertices, limits.max_faces)), limits);
}

IndexedMesh parse_obj(std::string_view text, const MeshLimits& limits) {
    LineReader scan(text);
    prescan_obj(scan, limits);
    LineReader in(text);
    return read_obj(in, limits);
}

IndexedMesh parse_obj(const TextSource& source, const MeshLimits& limits) {
    LineReader scan(source);
    prescan_obj(scan, limits);
    LineReader in(source);
    return read_obj(in, limits);
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
