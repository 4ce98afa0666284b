namespace AcDream.Core.Dat;

/// <summary>
/// A multi-part model (portal dat id <c>0x02xxxxxx</c>): GfxObj parts placed by a pose, and the
/// shapes it collides with when it has no physics polygons (cylinders, spheres). Setup-local metres.
/// Physics reads <see cref="Parts"/>, <see cref="DefaultScale"/>, the <see cref="Placement.Default"/>
/// pose of <see cref="PlacementFrames"/> and <see cref="CylSpheres"/>; the rest is carried for callers.
/// </summary>
public sealed class Setup
{
    /// <summary>The setup's dat id, <c>0x02xxxxxx</c>.</summary>
    public uint Id { get; set; }

    /// <summary>The setup's flags, as stored.</summary>
    public uint Flags { get; set; }

    /// <summary>Number of parts; the length of <see cref="Parts"/>.</summary>
    public uint NumParts { get; set; }

    /// <summary>The GfxObj id of each part.</summary>
    public List<uint> Parts { get; set; } = [];

    /// <summary>Index of each part's parent part (0xFFFFFFFF for none); not read by physics.</summary>
    public List<uint> ParentIndex { get; set; } = [];

    /// <summary>Scale of each part (applied in the part's own frame, before its placement); empty means 1.</summary>
    public List<System.Numerics.Vector3> DefaultScale { get; set; } = [];

    /// <summary>The poses by placement; a static object stands in <see cref="Placement.Default"/> (parts at identity when absent).</summary>
    public Dictionary<Placement, AnimationFrame> PlacementFrames { get; set; } = [];

    /// <summary>Upright collision cylinders, setup-local.</summary>
    public List<CylSphere> CylSpheres { get; set; } = [];

    /// <summary>Collision spheres, setup-local; not read by this engine's ground physics.</summary>
    public List<Sphere> Spheres { get; set; } = [];

    /// <summary>Height of the model, metres.</summary>
    public float Height { get; set; }

    /// <summary>Radius of the model, metres.</summary>
    public float Radius { get; set; }

    /// <summary>How high the model itself steps up when it moves, metres.</summary>
    public float StepUpHeight { get; set; }

    /// <summary>How far the model itself steps down when it moves, metres.</summary>
    public float StepDownHeight { get; set; }
}
