// FaceParameterization (quadtri/far/limit_surface.h): OpenSubdiv's Bfr layout of a face's (u, v).
#include <cmath>
#include <string>

#include <quadtri/far/limit_surface.h>
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {

FaceParameterization FaceParameterization::of(Scheme scheme, int faceSize) {
    FaceParameterization p;
    p.faceSize = faceSize;
    if (faceSize == 4) {
        p.type = Type::Quad;
    } else if (faceSize == 3 && internal::rulesOf(scheme).triangleSplit() == internal::TriangleSplit::FourTriangles) {
        p.type = Type::Triangle;
    } else {
        // As many columns as make the layout about square (Bfr's choice, exactly).
        p.type = Type::QuadSubFaces;
        p.gridWidth = faceSize < 10 ? 2 + (faceSize > 4 ? 1 : 0) : 1 + int(std::sqrt(float(faceSize - 1)));
    }
    return p;
}

bool FaceParameterization::contains(double u, double v, double tolerance) const {
    if (!(std::isfinite(u) && std::isfinite(v))) return false;
    switch (type) {
    case Type::Quad:
        return u >= -tolerance && v >= -tolerance && u <= 1 + tolerance && v <= 1 + tolerance;
    case Type::Triangle:
        return u >= -tolerance && v >= -tolerance && u + v <= 1 + tolerance;
    case Type::QuadSubFaces:
        return subFaceAt(u, v, tolerance) >= 0;
    }
    return false;
}

int FaceParameterization::subFaceAt(double u, double v, double tolerance) const {
    if (tolerance < 0.25) {
        // The sub-faces' squares lie a half apart, farther than two tolerances: the one that can
        // hold u is at floor(u + tolerance) (no division per sub-face, once per point).
        if (!(std::isfinite(u) && std::isfinite(v))) return -1;
        const double x = std::floor(u + tolerance), y = std::floor(v + tolerance);
        if (x < 0 || y < 0 || x >= gridWidth || u > x + 0.5 + tolerance || v > y + 0.5 + tolerance) return -1;
        const double i = y * gridWidth + x;
        return i < faceSize ? int(i) : -1;
    }
    for (int i = 0; i < faceSize; ++i) {
        const double x = i % gridWidth, y = i / gridWidth;
        if (u >= x - tolerance && u <= x + 0.5 + tolerance && v >= y - tolerance && v <= y + 0.5 + tolerance)
            return i;
    }
    return -1;
}

void FaceParameterization::cornerCoord(int corner, double& u, double& v) const {
    switch (type) {
    case Type::Quad:
        u = (corner == 1 || corner == 2) ? 1 : 0;
        v = corner >= 2 ? 1 : 0;
        return;
    case Type::Triangle:
        u = corner == 1 ? 1 : 0;
        v = corner == 2 ? 1 : 0;
        return;
    case Type::QuadSubFaces:
        u = corner % gridWidth;
        v = corner / gridWidth;
        return;
    }
}

void FaceParameterization::edgeCoord(int edge, double t, double& u, double& v) const {
    if (type == Type::QuadSubFaces) {  // half in corner i's sub-face, half in corner i + 1's
        cornerCoord(t < 0.5 ? edge : (edge + 1) % faceSize, u, v);
        if (t < 0.5)
            u += t;
        else
            v += 1 - t;
        return;
    }
    double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    cornerCoord(edge, u0, v0);
    cornerCoord((edge + 1) % faceSize, u1, v1);
    u = u0 + t * (u1 - u0);
    v = v0 + t * (v1 - v0);
}

std::string FaceParameterization::describe() const {
    switch (type) {
    case Type::Quad:
        return "a quad: 0 <= u, v <= 1";
    case Type::Triangle:
        return "a triangle: u, v >= 0 and u + v <= 1";
    case Type::QuadSubFaces:
        return "a " + std::to_string(faceSize) + "-sided face: " + std::to_string(faceSize) +
               " squares [x, x + 0.5] x [y, y + 0.5] at x = i % " + std::to_string(gridWidth) + ", y = i / " +
               std::to_string(gridWidth);
    }
    return {};
}

}  // namespace v0
}  // namespace quadtri
