// light_group (reference manual 3.4.7.11 "Light Groups"): a union whose light sources light
// only the objects inside it; `global_lights on` lets the scene's other lights light them too.
// The group's lights keep the shadows of every object in the scene.
//
// The rules are resolved here, onto the IR (scene::Light::group, scene::Object::light_group
// and no_global_lights), as POV-Ray resolves them while parsing:
// - only the light sources written directly in the group are its lights; one inside a union in
//   the group stays a global light;
// - the objects inside nested CSG get the group: a nested light_group's objects keep their own
//   group's lights (the outer group's do not reach them), but the outermost group's
//   global_lights setting decides for all of them;
// - but a nested group that is a copy of a declared one (`object { G }`) lets the lights of
//   the group just around it in too (POV-Ray clears a copy's light list, so the outer group's
//   promotion walks into it): Light::also_groups.
// The group's own union carries its id too (harmless: its shapes all have one), which marks
// where the groups are in a declared object that is copied.
#include <algorithm>
#include <utility>
#include <variant>
#include <vector>

#include "formats/pov/object_bodies.h"

namespace glint::pov {

namespace {

bool is_csg(const PovObject& o) { return std::holds_alternative<scene::Csg>(o.obj.shape); }

// The group's objects, down to the shapes inside CSG.
void mark_objects(PovObject& o, int group, bool no_global) {
    if (is_csg(o) && !o.children.empty()) {
        for (PovObject& c : o.children.edit()) mark_objects(c, group, no_global);
        return;
    }
    if (o.obj.light_group < 0) o.obj.light_group = group;
    o.obj.no_global_lights = no_global;
}

bool is_group(const PovObject& o) { return is_csg(o) && o.obj.light_group >= 0; }

// The outermost groups inside `o` (o itself included).
void outermost_groups(const PovObject& o, std::vector<int>* ids) {
    if (is_group(o)) {
        ids->push_back(o.obj.light_group);
        return;
    }
    for (const PovObject& c : o.children.given()) outermost_groups(c, ids);
}

void let_in(std::vector<scene::Light>& lights, int group, const std::vector<int>& nested) {
    for (scene::Light& l : lights)
        if (l.group == group)
            l.also_groups.insert(l.also_groups.end(), nested.begin(), nested.end());
}

// In a copy: each group's lights light the copied groups just inside it.
void link_copied(const PovObject& o, std::vector<scene::Light>& lights) {
    if (is_group(o)) {
        std::vector<int> nested;
        for (const PovObject& c : o.children.given()) outermost_groups(c, &nested);
        let_in(lights, o.obj.light_group, nested);
    }
    for (const PovObject& c : o.children.given()) link_copied(c, lights);
}

void collect_groups(const PovObject& o, std::vector<int>* ids) {
    if (o.obj.light_group >= 0) ids->push_back(o.obj.light_group);
    for (const scene::Light& l : o.lights)
        if (l.group >= 0) ids->push_back(l.group);
    for (const PovObject& c : o.children.given()) collect_groups(c, ids);
}

void renumber(PovObject& o, const std::vector<std::pair<int, int>>& map) {
    auto remap = [&](int& id) {
        for (const auto& [from, to] : map)
            if (id == from) {
                id = to;
                return;
            }
    };
    if (o.obj.light_group >= 0) remap(o.obj.light_group);
    for (scene::Light& l : o.lights) {
        if (l.group >= 0) remap(l.group);
        for (int& g : l.also_groups) remap(g);
    }
    for (PovObject& c : o.children.edit()) renumber(c, map);
}

}  // namespace

// light_group { light_source {..}... objects... [translate|rotate|scale|matrix|transform]...
// [global_lights [B]] }: the modifiers are read here (POV-Ray allows no others).
BodyEnd light_group_body(Parser& p, const ObjectStart& start, PovObject& po) {
    const int group = p.new_light_group(false);
    po.obj.shape = scene::Csg{};  // a union
    for (;;) {
        const Token& t = p.next();
        PovObject child;
        if (!p.parse_object(t, child)) {
            p.unget();
            break;
        }
        if (child.is_light) {
            for (scene::Light& l : child.lights) {
                if (l.group < 0) l.group = group;
                po.lights.push_back(l);
            }
            continue;
        }
        for (scene::Light& l : child.lights) po.lights.push_back(l);
        child.lights.clear();
        if (!child.left_out.empty()) po.left_out = child.left_out;
        else po.children.push_back(std::move(child));
    }
    if (!po.children.empty()) po.left_out.clear();
    bool global_lights = false;
    Transform tr;
    for (;;) {
        if (p.parse_transform_item(tr)) continue;
        if (p.accept("global_lights")) {
            global_lights = p.allow_float(1) > 0.5;
            continue;
        }
        if (p.accept("photons")) {
            p.parse_object_photons(po.obj);
            continue;
        }
        break;
    }
    p.expect_close("light_group", start.opened);
    for (PovObject& c : po.children.edit()) mark_objects(c, group, !global_lights);
    std::vector<int> nested, copied;
    for (const PovObject& c : po.children.given()) outermost_groups(c, &nested);
    for (int id : nested)
        if (p.is_copied_light_group(id)) copied.push_back(id);
    let_in(po.lights, group, copied);
    po.obj.light_group = group;
    p.apply_transform(po, tr);
    return BodyEnd::Done;
}

void give_light_groups_new_ids(Parser& p, PovObject& o) {
    std::vector<int> ids;
    collect_groups(o, &ids);
    if (ids.empty()) return;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<std::pair<int, int>> map;
    for (int id : ids) map.emplace_back(id, p.new_light_group(true));
    renumber(o, map);
    link_copied(o, o.lights);
}

}  // namespace glint::pov
