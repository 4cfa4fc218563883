#include "skeleton/plant_description.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <fmt/format.h>

namespace simeco::skeleton {

namespace {

struct Keyword {
    const char* word;
    Phyllotaxy phyllotaxy = Phyllotaxy::Unsaid;
    const char* shape = nullptr;
    Habit habit = Habit::Unsaid;
};

// English and the thesis' Chinese (traditional) terms.
const Keyword kKeywords[] = {
    {"alternate", Phyllotaxy::Alternate},  {"互生", Phyllotaxy::Alternate},
    {"opposite", Phyllotaxy::Opposite},    {"decussate", Phyllotaxy::Opposite},  {"對生", Phyllotaxy::Opposite},
    {"whorled", Phyllotaxy::Whorled},      {"verticillate", Phyllotaxy::Whorled}, {"輪生", Phyllotaxy::Whorled},
    {"basal", Phyllotaxy::Basal},          {"rosette", Phyllotaxy::Basal},       {"基生", Phyllotaxy::Basal},
    {"clustered", Phyllotaxy::Clustered},  {"fascicled", Phyllotaxy::Clustered}, {"叢生", Phyllotaxy::Clustered},
    {"ovate", Phyllotaxy::Unsaid, "ovate"},           {"卵形", Phyllotaxy::Unsaid, "ovate"},
    {"lanceolate", Phyllotaxy::Unsaid, "lanceolate"}, {"披針形", Phyllotaxy::Unsaid, "lanceolate"},
    {"linear", Phyllotaxy::Unsaid, "lanceolate"},     {"線形", Phyllotaxy::Unsaid, "lanceolate"},
    {"cordate", Phyllotaxy::Unsaid, "cordate"},       {"心形", Phyllotaxy::Unsaid, "cordate"},
    {"compound", Phyllotaxy::Unsaid, "compound"},     {"pinnate", Phyllotaxy::Unsaid, "compound"},
    {"羽狀複葉", Phyllotaxy::Unsaid, "compound"},     {"複葉", Phyllotaxy::Unsaid, "compound"},
    {"trifoliate", Phyllotaxy::Unsaid, "trifoliate"}, {"三出複葉", Phyllotaxy::Unsaid, "trifoliate"},
    {"serrate", Phyllotaxy::Unsaid, "serrate"},       {"鋸齒", Phyllotaxy::Unsaid, "serrate"},
    {"herb", Phyllotaxy::Unsaid, nullptr, Habit::Herb},   {"herbaceous", Phyllotaxy::Unsaid, nullptr, Habit::Herb},
    {"草本", Phyllotaxy::Unsaid, nullptr, Habit::Herb},
    {"shrub", Phyllotaxy::Unsaid, nullptr, Habit::Shrub}, {"bush", Phyllotaxy::Unsaid, nullptr, Habit::Shrub},
    {"灌木", Phyllotaxy::Unsaid, nullptr, Habit::Shrub},
    {"tree", Phyllotaxy::Unsaid, nullptr, Habit::Tree},   {"喬木", Phyllotaxy::Unsaid, nullptr, Habit::Tree},
};

std::string lower(std::string s) {
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x80) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Words split at commas, semicolons, slashes, white space and the Chinese enumeration comma and comma.
std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    std::string word;
    auto flush = [&] {
        if (!word.empty()) out.push_back(lower(word));
        word.clear();
    };
    for (size_t i = 0; i < text.size();) {
        if (text.compare(i, 3, "、") == 0 || text.compare(i, 3, "，") == 0) {
            flush();
            i += 3;
            continue;
        }
        char c = text[i];
        if (c == ',' || c == ';' || c == '/' || std::isspace(static_cast<unsigned char>(c))) flush();
        else word += c;
        ++i;
    }
    flush();
    return out;
}

std::string knownWords() {
    std::string out;
    for (const Keyword& k : kKeywords) out += (out.empty() ? "" : ", ") + std::string(k.word);
    return out;
}

} // namespace

const char* phyllotaxyName(Phyllotaxy p) {
    switch (p) {
    case Phyllotaxy::Alternate: return "alternate";
    case Phyllotaxy::Opposite: return "opposite";
    case Phyllotaxy::Whorled: return "whorled";
    case Phyllotaxy::Basal: return "basal";
    case Phyllotaxy::Clustered: return "clustered";
    case Phyllotaxy::Unsaid: break;
    }
    return "unsaid";
}

const char* habitName(Habit h) {
    switch (h) {
    case Habit::Herb: return "herb";
    case Habit::Shrub: return "shrub";
    case Habit::Tree: return "tree";
    case Habit::Unsaid: break;
    }
    return "unsaid";
}

PlantDescription describePlant(const std::string& text) {
    PlantDescription d;
    for (const std::string& w : words(text)) {
        auto k = std::find_if(std::begin(kKeywords), std::end(kKeywords),
                              [&](const Keyword& known) { return w == known.word; });
        if (k == std::end(kKeywords))
            throw std::invalid_argument(
                fmt::format("unknown word '{}' in the description (known: {})", w, knownWords()));
        if (k->phyllotaxy != Phyllotaxy::Unsaid) {
            d.phyllotaxy = k->phyllotaxy;
            d.understood.push_back(phyllotaxyName(k->phyllotaxy));
        } else if (k->shape) {
            d.leafShape = k->shape;
            d.understood.push_back(k->shape);
        } else {
            d.habit = k->habit;
            d.understood.push_back(habitName(k->habit));
        }
    }
    return d;
}

} // namespace simeco::skeleton
