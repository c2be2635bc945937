#include "rays/scene/shapes/parametric.h"

#include <cmath>
#include <vector>

#include "rays/fn/compile.h"
#include "rays/fn/machine.h"
#include "rays/fn/program.h"

namespace rays {

namespace {

struct ParametricEval {
    const ParametricSpec& spec;
    fn::Scratch scratch;
    Vec3 at(double u, double v) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const fn::Program& f = *spec.f[k];
            if (!scratch.fitsScalar(f)) scratch.fit(f);
            double args[fn::kMaxParams] = {u, v, 0};
            p[k] = fn::eval(f, args, scratch);
        }
        return p;
    }
};

bool insideContainer(const ParametricSpec& s, Vec3 p) {
    if (s.sphere) return dot(p - s.centre, p - s.centre) <= s.radius * s.radius;
    return p.x >= s.lo.x && p.y >= s.lo.y && p.z >= s.lo.z && p.x <= s.hi.x && p.y <= s.hi.y && p.z <= s.hi.z;
}

}  // namespace

void tessellateParametric(const ParametricSpec& spec, Mesh& mesh) {
    ParametricEval e{spec, {}};
    const int n = kParametricGrid;
    const double du = (spec.u2 - spec.u1) / n, dv = (spec.v2 - spec.v1) / n;
    const double hu = 1e-4 * (std::fabs(du) + 1e-12), hv = 1e-4 * (std::fabs(dv) + 1e-12);
    std::vector<char> in(size_t((n + 1) * (n + 1)));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double u = spec.u1 + i * du, v = spec.v1 + j * dv;
            const Vec3 p = e.at(u, v);
            Vec3 nrm = cross(e.at(u + hu, v) - e.at(u - hu, v), e.at(u, v + hv) - e.at(u, v - hv));
            if (length(nrm) > 0) nrm = normalize(nrm);
            mesh.positions.insert(mesh.positions.end(), {float(p.x), float(p.y), float(p.z)});
            mesh.normals.insert(mesh.normals.end(), {float(nrm.x), float(nrm.y), float(nrm.z)});
            mesh.uvs.insert(mesh.uvs.end(), {float(u), float(v)});
            in[size_t(j * (n + 1) + i)] = std::isfinite(p.x + p.y + p.z) && insideContainer(spec, p);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t k = uint32_t(j * (n + 1) + i), up = k + uint32_t(n + 1);
            if (!in[k] || !in[k + 1] || !in[up] || !in[up + 1]) continue;
            for (uint32_t v : {k, k + 1, up + 1, k, up + 1, up}) {
                mesh.indices.push_back(v);
                mesh.normalIndices.push_back(v);
                mesh.uvIndices.push_back(v);
            }
        }
}

}  // namespace rays
