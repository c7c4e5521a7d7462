#pragma once
// The subjects of the procedural scenes (fur, metal tubes, foliage, bamboo,
// railings) and their backdrops (floor, wall). Each builder appends meshes to a
// SubjectSink, which tracks the subject's bounds so scenegen can frame the
// camera and place the lights around it. All sizes in metres, +Y up.

#include "engine/scene/model_builder.h"
#include "engine/scene/prng.h"

#include <map>
#include <string>

namespace eng::scene {

class SubjectSink {
  public:
    SubjectSink(ModelBuilder& builder, Prng& rng, float density);

    ModelBuilder& builder() { return m_builder; }
    Prng& rng() { return m_rng; }
    // Scales strand, leaf and bar counts (1 = the documented triangle budgets).
    float density() const { return m_density; }
    // count * density, at least 1.
    int scaled(int count) const;

    // One glTF material per name: scenes combining subjects share them.
    int material(const MaterialDesc& desc);
    int leafMaterial();

    void addSubject(const std::string& name, const MeshData& mesh, int material);
    void addBackdrop(const std::string& name, const MeshData& mesh, int material);

    bool hasSubject() const { return m_hasSubject; }
    const Bounds& subjectBounds() const { return m_subject; }
    const std::vector<glm::vec3>& subjectPoints() const { return m_points; }

  private:
    ModelBuilder& m_builder;
    Prng& m_rng;
    float m_density;
    std::map<std::string, int> m_materials;
    int m_leafTexture = -1;
    Bounds m_subject;
    std::vector<glm::vec3> m_points; // every subject vertex, for camera framing
    bool m_hasSubject = false;
};

// Sphere of `radius` covered in thousands of tapered, curved hair strands
// (triangular prisms, 1-2 mm wide, 5-15 cm long); strandScale scales the count.
void addFurball(SubjectSink& sink, const glm::vec3& centre, float radius, float strandScale = 1.0f);

// A lattice of thin glossy metal tubes (3-5 mm radius, 10 sides), some bent,
// spanning size.x by size.y in a plane facing +Z.
void addMetalLattice(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& size);

// A ball of thin glossy gold spikes (issue 14's thin glossy metal): `count` cylinders of 2.5 mm
// radius running radially from 0.3 to 1 x radius, metallic 1, roughness 0.02, directions spread
// evenly over the sphere (a Fibonacci lattice with a seeded jitter).
void addSpikeBall(SubjectSink& sink, const glm::vec3& centre, float radius, int count);

// A chain-link fence (issue 49: the content AGAA exists for): two families of woven wires at
// +-45 degrees, `mesh` metres apart, 4 mm radius, galvanised steel (metallic 1, roughness 0.15),
// spanning size.x by size.y in a plane facing +Z; each wire passes alternately over and under
// the other family's at their crossings.
void addChainLink(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& size, float mesh);

// Branching twigs carrying alpha-masked leaf cards, rising from base.
void addFoliage(SubjectSink& sink, const glm::vec3& base, float width, float height);

// A grove of thin vertical bamboo stalks with nodes and leaf cards.
void addBamboo(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& area, float height);

// Thin parallel vertical bars between a top and a bottom rail.
void addRailing(SubjectSink& sink, const glm::vec3& baseCentre, float width, float height);

// Backdrops: a floor at height y, and a wall facing +Z at depth z.
void addFloor(SubjectSink& sink, float y, float halfSize, const glm::vec3& color);
void addWall(SubjectSink& sink, float z, float halfWidth, float bottom, float top, const glm::vec3& color);

} // namespace eng::scene
