// Reading three views from an SVG drawing (three_views.h): a small XML reader that keeps every byte's place for
// errors, and the straight-line subset of SVG's polyline and path syntax.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "skeleton/three_views.h"

namespace simeco::skeleton {

namespace {

constexpr std::array<const char*, 3> kViewNames{"front", "side", "top"};

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// XML's predefined entities and ASCII character references; anything else is kept as written.
std::string decoded(std::string_view raw) {
    std::string out;
    for (size_t k = 0; k < raw.size(); ++k) {
        size_t semicolon = raw[k] == '&' ? raw.find(';', k) : std::string_view::npos;
        if (semicolon == std::string_view::npos) {
            out += raw[k];
            continue;
        }
        std::string_view name = raw.substr(k + 1, semicolon - k - 1);
        int code = -1;
        if (name == "lt")
            code = '<';
        else if (name == "gt")
            code = '>';
        else if (name == "amp")
            code = '&';
        else if (name == "quot")
            code = '"';
        else if (name == "apos")
            code = '\'';
        else if (name.size() > 1 && name[0] == '#') {
            bool hex = name[1] == 'x';
            std::string_view digits = name.substr(hex ? 2 : 1);
            int value = 0;
            auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value, hex ? 16 : 10);
            if (error == std::errc() && end == digits.data() + digits.size() && value > 0 && value < 128) code = value;
        }
        if (code < 0) {
            out += raw[k];
            continue;
        }
        out += char(code);
        k = semicolon;
    }
    return out;
}

struct Attribute {
    std::string name;
    std::string_view raw; // as written, for numbers read at their own places
    std::string value;    // entities decoded
    size_t at = 0;        // the offset of the value's first character
};

struct Tag {
    std::string name; // without a namespace prefix
    size_t at = 0;    // the offset of its '<'
    std::vector<Attribute> attributes;
    bool selfClosing = false;

    const Attribute* find(std::string_view attribute) const {
        for (const Attribute& a : attributes)
            if (a.name == attribute) return &a;
        return nullptr;
    }
};

// An element not yet closed, with what it passes on to the elements inside it.
struct OpenElement {
    std::string name;
    size_t at = 0;
    int view = -1;                   // the view group it is or is inside (an index into kViewNames)
    std::optional<size_t> transform; // the offset of a transform on it or on an element around it
};

class SvgReader {
public:
    SvgReader(const std::string& text, const std::string& file) : text_(text), file_(file) {
        for (size_t k = 0; k < text.size(); ++k)
            if (text[k] == '\n') lineStarts_.push_back(k + 1);
    }

    ThreeViews read() {
        std::array<View*, 3> views{&views_.front, &views_.side, &views_.top};
        for (size_t lt = text_.find('<'); lt != std::string::npos; lt = text_.find('<', at_)) {
            at_ = lt;
            if (startsWith("<!--"))
                skipPast("-->", "a comment");
            else if (startsWith("<![CDATA["))
                skipPast("]]>", "a CDATA section");
            else if (startsWith("<?"))
                skipPast("?>", "a processing instruction");
            else if (startsWith("<!"))
                skipDeclaration();
            else if (startsWith("</"))
                closeElement();
            else
                openElement(readTag(), views);
        }
        if (!open_.empty()) fail(open_.back().at, fmt::format("'<{}>' is never closed", open_.back().name));
        for (size_t v = 0; v < 3; ++v)
            if (!seen_[v])
                throw ir::InputError({file_, 0, 0}, fmt::format("the drawing has no {0} view: expected a group "
                                                                "<g id=\"{0}\"> holding its stems",
                                                                kViewNames[v]));
        return views_;
    }

    ir::SourceLoc where(size_t offset) const {
        size_t line = size_t(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset) - lineStarts_.begin());
        return {file_, int(line), int(offset - lineStarts_[line - 1]) + 1};
    }

    [[noreturn]] void fail(size_t offset, const std::string& message) const {
        throw ir::InputError(where(offset), message);
    }

private:
    const std::string& text_;
    const std::string& file_;
    std::vector<size_t> lineStarts_{0};
    size_t at_ = 0;
    std::vector<OpenElement> open_;
    ThreeViews views_;
    std::array<bool, 3> seen_{};
    std::array<size_t, 3> viewAt_{};

    bool startsWith(std::string_view s) const { return text_.compare(at_, s.size(), s) == 0; }

    void skipPast(std::string_view end, const char* what) {
        size_t found = text_.find(end, at_);
        if (found == std::string::npos) fail(at_, fmt::format("{} that is never closed with '{}'", what, end));
        at_ = found + end.size();
    }

    // <!DOCTYPE ...>, with an internal subset in brackets that may hold '>' of its own.
    void skipDeclaration() {
        size_t start = at_;
        for (int depth = 0; at_ < text_.size(); ++at_) {
            if (text_[at_] == '[')
                ++depth;
            else if (text_[at_] == ']')
                --depth;
            else if (text_[at_] == '>' && depth <= 0) {
                ++at_;
                return;
            }
        }
        fail(start, "a declaration that is never closed with '>'");
    }

    void skipSpaces(size_t& k) const {
        while (k < text_.size() && isSpace(text_[k]))
            ++k;
    }

    std::string readName(size_t& k) const {
        size_t start = k;
        while (k < text_.size() && !isSpace(text_[k]) && text_[k] != '/' && text_[k] != '>' && text_[k] != '=' &&
               text_[k] != '<')
            ++k;
        return text_.substr(start, k - start);
    }

    static std::string localName(const std::string& name) { return name.substr(name.rfind(':') + 1); }

    void closeElement() {
        size_t k = at_ + 2;
        std::string name = localName(readName(k));
        skipSpaces(k);
        if (k >= text_.size() || text_[k] != '>') fail(k, fmt::format("expected '>' to end '</{}'", name));
        if (open_.empty()) fail(at_, fmt::format("'</{}>' closes no element", name));
        if (open_.back().name != name)
            fail(at_,
                 fmt::format("'</{}>' closes '<{}>' of line {}", name, open_.back().name, where(open_.back().at).line));
        open_.pop_back();
        at_ = k + 1;
    }

    Tag readTag() {
        Tag tag;
        tag.at = at_;
        size_t k = at_ + 1;
        tag.name = localName(readName(k));
        if (tag.name.empty()) fail(k, "expected an element name after '<'");
        while (true) {
            skipSpaces(k);
            if (k >= text_.size()) fail(tag.at, fmt::format("'<{}' is never closed with '>'", tag.name));
            if (text_.compare(k, 2, "/>") == 0) {
                tag.selfClosing = true;
                k += 2;
                break;
            }
            if (text_[k] == '>') {
                ++k;
                break;
            }
            size_t nameAt = k;
            std::string name = readName(k);
            if (name.empty()) fail(k, fmt::format("unexpected '{}' in '<{}'", text_[k], tag.name));
            skipSpaces(k);
            if (k >= text_.size() || text_[k] != '=') fail(k, fmt::format("expected '=' after '{}'", name));
            ++k;
            skipSpaces(k);
            if (k >= text_.size() || (text_[k] != '"' && text_[k] != '\''))
                fail(k, fmt::format("expected the value of '{}' in quotes", name));
            size_t close = text_.find(text_[k], k + 1);
            if (close == std::string::npos) fail(nameAt, fmt::format("the value of '{}' is never closed", name));
            std::string_view raw = std::string_view(text_).substr(k + 1, close - k - 1);
            tag.attributes.push_back({name, raw, decoded(raw), k + 1});
            k = close + 1;
        }
        at_ = k;
        return tag;
    }

    void openElement(const Tag& tag, const std::array<View*, 3>& views) {
        OpenElement element{tag.name, tag.at, -1, std::nullopt};
        if (!open_.empty()) {
            element.view = open_.back().view;
            element.transform = open_.back().transform;
        }
        if (const Attribute* t = tag.find("transform")) element.transform = t->at;
        const Attribute* id = tag.find("id");
        auto named =
            id ? std::find(kViewNames.begin(), kViewNames.end(), std::string_view(id->value)) : kViewNames.end();
        if (tag.name == "g" && named != kViewNames.end()) {
            int v = int(named - kViewNames.begin());
            if (element.view >= 0)
                fail(tag.at, fmt::format("the {} view is inside the {} view", kViewNames[v], kViewNames[element.view]));
            if (seen_[v])
                fail(tag.at,
                     fmt::format("a second {} view (the first is on line {})", kViewNames[v], where(viewAt_[v]).line));
            seen_[v] = true;
            viewAt_[v] = tag.at;
            element.view = v;
            refuseTransform(element);
        }
        if (tag.find("data-stem")) {
            refuseTransform(element);
            ViewStem s = stem(tag, element.view);
            views[size_t(element.view)]->stems.push_back(std::move(s));
        }
        if (!tag.selfClosing) open_.push_back(std::move(element));
    }

    void refuseTransform(const OpenElement& element) const {
        if (element.transform)
            fail(*element.transform, "a transform would move or scale the views: give the points in world units, "
                                     "without transforms");
    }

    ViewStem stem(const Tag& tag, int view) const {
        ViewStem s;
        s.where = where(tag.at);
        s.id = integer(*tag.find("data-stem"));
        if (view < 0)
            fail(tag.at, fmt::format("stem {} is outside the views: draw it inside <g id=\"front\">, <g id=\"side\"> "
                                     "or <g id=\"top\">",
                                     s.id));
        if (const Attribute* parent = tag.find("data-parent")) s.parent = integer(*parent);
        if (const Attribute* width = tag.find("data-width")) s.width = nonNegative(*width);
        if (tag.name == "polyline") {
            const Attribute* points = tag.find("points");
            if (!points) fail(tag.at, fmt::format("stem {}'s polyline has no 'points'", s.id));
            s.points = polylinePoints(*points);
        } else if (tag.name == "path") {
            const Attribute* d = tag.find("d");
            if (!d) fail(tag.at, fmt::format("stem {}'s path has no 'd'", s.id));
            s.points = pathPoints(*d);
        } else {
            fail(tag.at, fmt::format("stem {} is a <{}>: draw a stem as a <polyline> or a <path>", s.id, tag.name));
        }
        for (glm::dvec2& p : s.points)
            p.y = -p.y; // SVG's y grows downward, a view's v upward
        return s;
    }

    int integer(const Attribute& a) const {
        int v = 0;
        const std::string& s = a.value;
        auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || error != std::errc() || end != s.data() + s.size())
            fail(a.at, fmt::format("{}=\"{}\" is not a whole number", a.name, s));
        return v;
    }

    double nonNegative(const Attribute& a) const {
        double v = 0.0;
        const std::string& s = a.value;
        auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || error != std::errc() || end != s.data() + s.size() || !std::isfinite(v) || v < 0.0)
            fail(a.at, fmt::format("{}=\"{}\" is not a number of zero or more", a.name, s));
        return v;
    }

    // Reads the numbers of a 'points' or 'd' value by SVG's grammar ("1.5.5" is 1.5 and .5, "10-5" is 10 and -5),
    // separated by white space and commas.
    class Numbers {
    public:
        Numbers(const SvgReader& reader, const Attribute& a) : reader_(reader), a_(a) {}

        void skipSeparators() {
            while (k_ < a_.raw.size() && (isSpace(a_.raw[k_]) || a_.raw[k_] == ','))
                ++k_;
        }
        bool done() const { return k_ >= a_.raw.size(); }
        char peek() const { return a_.raw[k_]; }
        size_t offset() const { return a_.at + k_; }
        void advance() { ++k_; }
        bool atNumber() const {
            return !done() && (isDigit(peek()) || peek() == '.' || peek() == '-' || peek() == '+');
        }

        double number(const char* what) {
            skipSeparators();
            if (!atNumber()) {
                if (done())
                    reader_.fail(a_.at + a_.raw.size(), fmt::format("'{}' ends where {} was expected", a_.name, what));
                reader_.fail(offset(), fmt::format("unexpected '{}' in '{}': expected {}", peek(), a_.name, what));
            }
            size_t start = k_;
            std::string_view s = a_.raw;
            if (s[k_] == '-' || s[k_] == '+') ++k_;
            size_t digits = 0;
            for (; k_ < s.size() && isDigit(s[k_]); ++k_)
                ++digits;
            if (k_ < s.size() && s[k_] == '.')
                for (++k_; k_ < s.size() && isDigit(s[k_]); ++k_)
                    ++digits;
            if (digits == 0) reader_.fail(a_.at + start, fmt::format("'{}' has a malformed number", a_.name));
            if (k_ < s.size() && (s[k_] == 'e' || s[k_] == 'E')) {
                size_t e = k_ + 1;
                if (e < s.size() && (s[e] == '-' || s[e] == '+')) ++e;
                if (e < s.size() && isDigit(s[e])) {
                    k_ = e;
                    while (k_ < s.size() && isDigit(s[k_]))
                        ++k_;
                }
            }
            std::string_view text = s.substr(start, k_ - start);
            if (text[0] == '+') text.remove_prefix(1); // from_chars takes no '+'
            double v = 0.0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
            if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
                reader_.fail(a_.at + start, fmt::format("'{}' is not a finite number", s.substr(start, k_ - start)));
            return v;
        }

    private:
        const SvgReader& reader_;
        const Attribute& a_;
        size_t k_ = 0;
    };

    std::vector<glm::dvec2> polylinePoints(const Attribute& a) const {
        Numbers numbers(*this, a);
        std::vector<glm::dvec2> points;
        for (numbers.skipSeparators(); !numbers.done(); numbers.skipSeparators()) {
            double x = numbers.number("a number");
            points.push_back({x, numbers.number("the point's y")});
        }
        if (points.empty()) fail(a.at, "'points' holds no points");
        return points;
    }

    // A path of straight segments: M, L, H and V, absolute (upper case) or relative (lower case). A pair of
    // numbers after a move continues as a line, as SVG reads it.
    std::vector<glm::dvec2> pathPoints(const Attribute& a) const {
        Numbers numbers(*this, a);
        std::vector<glm::dvec2> points;
        glm::dvec2 current(0.0);
        char command = 0;
        for (numbers.skipSeparators(); !numbers.done(); numbers.skipSeparators()) {
            if (isLetter(numbers.peek())) {
                command = numbers.peek();
                size_t at = numbers.offset();
                char upper = char(command & ~0x20);
                if (upper == 'Z') fail(at, "'Z' closes the path: a stem is an open polyline");
                if (std::string_view("CSQTA").find(upper) != std::string_view::npos)
                    fail(at, fmt::format("a curve ('{}'): draw a stem with straight segments (M, L, H, V), flattening "
                                         "its curves first",
                                         command));
                if (std::string_view("MLHV").find(upper) == std::string_view::npos)
                    fail(at, fmt::format("unknown path command '{}'", command));
                if (upper == 'M' && !points.empty())
                    fail(at, "a second move ('M'): a stem is one polyline, drawn without lifting the pen");
                if (upper != 'M' && points.empty()) fail(at, "a path starts with a move ('M')");
                numbers.advance();
                numbers.skipSeparators();
                if (!numbers.atNumber()) fail(numbers.offset(), fmt::format("expected a number after '{}'", command));
                continue;
            }
            if (command == 0) fail(numbers.offset(), "a path starts with a move ('M')");
            bool relative = command >= 'a';
            glm::dvec2 p = current;
            switch (command & ~0x20) {
            case 'M':
            case 'L': {
                double x = numbers.number("a number");
                double y = numbers.number("the point's y");
                p = relative ? current + glm::dvec2(x, y) : glm::dvec2(x, y);
                if ((command & ~0x20) == 'M') command = relative ? 'l' : 'L';
                break;
            }
            case 'H':
                p.x = (relative ? current.x : 0.0) + numbers.number("a number");
                break;
            case 'V':
                p.y = (relative ? current.y : 0.0) + numbers.number("a number");
                break;
            }
            points.push_back(p);
            current = p;
        }
        if (points.empty()) fail(a.at, "'d' holds no points");
        return points;
    }
};

} // namespace

std::string threeViewsSvg(const ThreeViews& views) {
    // Every view in the coordinates it is read in (a transform would be refused), SVG's y growing downward (a
    // view's v is -y): the three groups lie over one another, like layers to show one at a time.
    const View* all[3] = {&views.front, &views.side, &views.top};
    const char* names[3] = {"front", "side", "top"};
    double minU = 1e300, maxU = -1e300, minV = 1e300, maxV = -1e300;
    std::string body;
    for (int k = 0; k < 3; ++k) {
        body += fmt::format("  <g id=\"{}\">\n", names[k]);
        for (const ViewStem& s : all[k]->stems) {
            body += fmt::format("    <polyline data-stem=\"{}\"", s.id);
            if (k == 0 && s.parent) body += fmt::format(" data-parent=\"{}\"", *s.parent);
            if (k == 0 && s.width > 0.0) body += fmt::format(" data-width=\"{:.9g}\"", s.width);
            body += " points=\"";
            for (size_t j = 0; j < s.points.size(); ++j) {
                const glm::dvec2& p = s.points[j];
                body += fmt::format("{}{:.9g},{:.9g}", j ? " " : "", p.x, -p.y);
                minU = std::min(minU, p.x);
                maxU = std::max(maxU, p.x);
                minV = std::min(minV, p.y);
                maxV = std::max(maxV, p.y);
            }
            body += "\"/>\n";
        }
        body += "  </g>\n";
    }
    if (minU > maxU) minU = maxU = minV = maxV = 0.0;
    const double size = std::max({maxU - minU, maxV - minV, 1e-9}), margin = 0.05 * size;
    return fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.9g} {:.9g} {:.9g} {:.9g}\" "
                       "fill=\"none\" stroke=\"black\" stroke-width=\"{:.3g}\">\n{}</svg>\n",
                       minU - margin, -maxV - margin, maxU - minU + 2 * margin, maxV - minV + 2 * margin,
                       0.005 * size, body);
}

Skeleton parseThreeViewsSvg(const std::string& text, const std::string& file) {
    ThreeViews views = SvgReader(text, file).read();
    Skeleton skeleton;
    skeleton.source = file;
    skeleton.plants.push_back(plantFromThreeViews(views, file));
    return skeleton;
}

} // namespace simeco::skeleton
