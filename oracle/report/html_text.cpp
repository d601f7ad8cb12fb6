// Text for the report's pages (html_text.h).
#include "oracle/report/html_text.h"

#include <cstdio>

namespace raster::oracle {

std::string escape_html(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string number(const nlohmann::json& value) {
    if (value.is_number_float()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", value.get<double>());
        return text;
    }
    return value.is_number() ? value.dump() : "-";
}

std::string percent(const nlohmann::json& value) {
    if (!value.is_number()) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.4f%%", 100.0 * value.get<double>());
    return text;
}

std::string fixed(const nlohmann::json& value, int digits) {
    if (!value.is_number()) return "-";
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", digits, value.get<double>());
    return text;
}

nlohmann::json field(const nlohmann::json& object, const char* key) {
    return object.is_object() && object.contains(key) ? object[key] : nlohmann::json();
}

std::string text(const nlohmann::json& object, const char* key) {
    const nlohmann::json value = field(object, key);
    return value.is_string() ? value.get<std::string>() : "";
}

std::vector<nlohmann::json> objects(const nlohmann::json& object, const char* key) {
    std::vector<nlohmann::json> out;
    const nlohmann::json list = field(object, key);
    if (list.is_array())
        for (const nlohmann::json& item : list)
            if (item.is_object()) out.push_back(item);
    return out;
}

}  // namespace raster::oracle
