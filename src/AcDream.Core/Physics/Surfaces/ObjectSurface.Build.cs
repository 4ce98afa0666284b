using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics;

// ObjectSurface, how a model is placed: a stab's or a building's model found among the GfxObjs and Setups,
// its ids checked, its parts and cylinders moved to landblock-local space and checked (Rigid, Placed).
public sealed partial class ObjectSurface
{
    private static ObjectSurface FromStab(Stab stab, uint cellId, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups)
    {
        ArgumentNullException.ThrowIfNull(stab);
        return new ObjectSurface(stab.Id, cellId, PlaceModel(stab.Id, stab.Frame, gfxObjs, setups, "stab"), isBuilding: false, []);
    }

    private static Placed PlaceModel(uint id, Frame frame, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups, string argument)
    {
        if (id >> 24 == 0x01 && gfxObjs.TryGetValue(id, out GfxObj? gfxObj))
        {
            return Place(gfxObj, frame);
        }

        if (id >> 24 == 0x02 && setups.TryGetValue(id, out Setup? setup))
        {
            return Place(setup, gfxObjs, frame);
        }

        throw new ArgumentException(
            id >> 24 is 0x01 or 0x02 ? $"{Name(id)}: not found among the {(id >> 24 == 0x01 ? "GfxObjs" : "Setups")} given."
            : $"{Name(id)}: not a GfxObj (0x01xxxxxx) or Setup (0x02xxxxxx) id.",
            argument);
    }

    private static Placed Place(GfxObj gfxObj, Frame frame)
    {
        ArgumentNullException.ThrowIfNull(gfxObj);
        var placed = new Placed(Name(gfxObj.Id), Rigid.Of(Name(gfxObj.Id), frame, "frame"));
        placed.AddPart(gfxObj, Vector3.One, Rigid.Identity);
        return placed;
    }

    private static Placed Place(Setup setup, IReadOnlyDictionary<uint, GfxObj> gfxObjs, Frame frame)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(gfxObjs);
        string name = Name(setup.Id);
        var placed = new Placed(name, Rigid.Of(name, frame, "frame"));
        List<uint> parts = setup.Parts ?? throw new ArgumentNullException(nameof(setup), $"{name}: setup.Parts is null.");
        List<Vector3> scales = setup.DefaultScale ?? [];
        List<Frame>? pose = setup.PlacementFrames is { } frames && frames.TryGetValue(Placement.Default, out AnimationFrame? animation) ? animation?.Frames : null;
        if (scales.Count != 0 && scales.Count != parts.Count)
        {
            throw new ArgumentException($"{name}: {scales.Count} default scales for {parts.Count} parts.", nameof(setup));
        }

        if (pose is not null && pose.Count != parts.Count)
        {
            throw new ArgumentException($"{name}: the default pose has {pose.Count} frames for {parts.Count} parts.", nameof(setup));
        }

        for (int i = 0; i < parts.Count; i++)
        {
            if (!gfxObjs.TryGetValue(parts[i], out GfxObj? part))
            {
                throw new ArgumentException($"{name}: part {i} (0x{parts[i]:X8}) is not among the GfxObjs given.", nameof(gfxObjs));
            }

            Vector3 scale = scales.Count == 0 ? Vector3.One : scales[i];
            if (!float.IsFinite(scale.X) || !float.IsFinite(scale.Y) || !float.IsFinite(scale.Z))
            {
                throw new ArgumentException($"{name}: part {i} has scale {scale}; scales must be finite.", nameof(setup));
            }

            placed.AddPart(part, scale, pose is null ? Rigid.Identity : Rigid.Of($"{name} part {i}", pose[i], nameof(setup)));
        }

        foreach ((CylSphere? cylinder, int i) in (setup.CylSpheres ?? []).Select((c, i) => (c, i)))
        {
            if (cylinder is null || !Geometry.IsFinite(cylinder.Origin) || !float.IsFinite(cylinder.Radius) || !float.IsFinite(cylinder.Height)
                || cylinder.Radius < 0f || cylinder.Height < 0f)
            {
                throw new ArgumentException(
                    $"{name}: cylinder {i} ({cylinder?.Origin}, radius {cylinder?.Radius}, height {cylinder?.Height}) must be finite with a radius and height ≥ 0.",
                    nameof(setup));
            }

            placed.AddCylinder(cylinder.Origin, cylinder.Radius, cylinder.Height);
        }

        return placed;
    }

    /// <summary>The model's id (null: the model is null), checked to be of <paramref name="kind"/> (its top byte).</summary>
    private static uint CheckedId(uint? id, uint kind, string argument)
    {
        if (id is not uint value)
        {
            throw new ArgumentNullException(argument);
        }

        if (value >> 24 != kind)
        {
            throw new ArgumentException($"{Name(value)}: not a {(kind == 0x01 ? "GfxObj (0x01xxxxxx)" : "Setup (0x02xxxxxx)")} id.", argument);
        }

        return value;
    }

    private static string Name(uint id) => $"object 0x{id:X8}";


    /// <summary>
    /// A rotation and translation, the rotation a unit quaternion: in floats (<see cref="Rotation"/>, normalised in double
    /// and rounded) for the placed vertices the movers meet, and in double (<see cref="Exact"/>, normalised in double)
    /// for the exact ones a cast meets.
    /// </summary>
    private readonly record struct Rigid(Quaternion Rotation, Vector3 Origin, Unit Exact)
    {
        public static Rigid Identity => new(Quaternion.Identity, Vector3.Zero, new Unit(0, 0, 0, 1));

        public static Rigid Of(string name, Frame? frame, string argument)
        {
            if (frame is null)
            {
                throw new ArgumentNullException(argument, $"{name}: the frame is null.");
            }

            if (!Geometry.IsFinite(frame.Origin) || !CellSurface.TryUnitOrientation(frame.Orientation, out Quaternion unit))
            {
                throw new ArgumentException($"{name}: frame ({frame.Origin}, {frame.Orientation}) is not a placement (non-finite, or an orientation shorter than 1e-6).", argument);
            }

            Quaternion q = frame.Orientation;
            double length = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
            return new Rigid(unit, frame.Origin, new Unit(q.X / length, q.Y / length, q.Z / length, q.W / length));
        }

        public Vector3 Apply(Vector3 v) => Origin + Vector3.Transform(v, Rotation);

        /// <summary><paramref name="v"/> placed in double precision: v + 2w(q × v) + 2q × (q × v), then moved by the origin.</summary>
        public D3 ApplyExact(D3 v)
        {
            (double qx, double qy, double qz, double qw) = (Exact.X, Exact.Y, Exact.Z, Exact.W);
            double cx = (qy * v.Z) - (qz * v.Y), cy = (qz * v.X) - (qx * v.Z), cz = (qx * v.Y) - (qy * v.X);
            double ccx = (qy * cz) - (qz * cy), ccy = (qz * cx) - (qx * cz), ccz = (qx * cy) - (qy * cx);
            return new D3(
                Origin.X + (v.X + (2 * ((qw * cx) + ccx))),
                Origin.Y + (v.Y + (2 * ((qw * cy) + ccy))),
                Origin.Z + (v.Z + (2 * ((qw * cz) + ccz))));
        }
    }

    /// <summary>A unit quaternion in double precision.</summary>
    private readonly record struct Unit(double X, double Y, double Z, double W);

    /// <summary>The placed physics polygons (each with its winding normal) and cylinders of one object, landblock-local.</summary>
    private sealed class Placed(string name, Rigid frame)
    {
        /// <summary>A copy moved by <paramref name="offset"/>.</summary>
        public Placed Shifted(Vector3 offset)
        {
            var moved = new Placed(name, frame);
            foreach ((ushort id, Vector3[] v, Vector3 n) in Polygons)
            {
                moved.Polygons.Add((id, Array.ConvertAll(v, p => p + offset), n));
            }

            foreach (D3[] v in Exact)
            {
                moved.Exact.Add(Array.ConvertAll(v, p => p + new D3(offset.X, offset.Y, offset.Z)));
            }

            foreach ((Vector3 b, float r, float h) in Cylinders)
            {
                moved.Cylinders.Add((b + offset, r, h));
            }

            return moved;
        }

        public List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> Polygons { get; } = [];

        /// <summary>The same polygons' vertices placed in double precision (<see cref="Rigid.ApplyExact"/>), in the same order.</summary>
        public List<D3[]> Exact { get; } = [];

        public List<(Vector3 Base, float Radius, float Height)> Cylinders { get; } = [];

        public void AddPart(GfxObj part, Vector3 scale, Rigid partFrame)
        {
            string what = part.Id == 0 ? name : $"{name} (part 0x{part.Id:X8})";
            Dictionary<ushort, Polygon> polygons = part.PhysicsPolygons
                ?? throw new ArgumentNullException("gfxObj", $"{what}: PhysicsPolygons is null.");
            Dictionary<ushort, SWVertex> vertices = part.VertexArray?.Vertices
                ?? throw new ArgumentNullException("gfxObj", $"{what}: VertexArray.Vertices is null.");
            var keys = new List<ushort>(polygons.Keys);
            keys.Sort();
            foreach (ushort key in keys)
            {
                List<short> ids = polygons[key]?.VertexIds
                    ?? throw new ArgumentNullException("gfxObj", $"{what}: physics polygon {key} or its VertexIds is null.");
                if (ids.Count < 3)
                {
                    throw new ArgumentException($"{what}: physics polygon {key} has {ids.Count} vertices; a polygon needs at least 3.", "gfxObj");
                }

                var v = new Vector3[ids.Count];
                var exact = new D3[ids.Count];
                for (int i = 0; i < v.Length; i++)
                {
                    if (ids[i] < 0 || !vertices.TryGetValue((ushort)ids[i], out SWVertex? vertex) || vertex is null)
                    {
                        throw new ArgumentException($"{what}: physics polygon {key} names vertex {ids[i]}, which the vertex array lacks.", "gfxObj");
                    }

                    if (!Geometry.IsFinite(vertex.Origin))
                    {
                        throw new ArgumentException($"{what}: vertex {ids[i]} (physics polygon {key}) is {vertex.Origin}; vertices must be finite.", "gfxObj");
                    }

                    v[i] = Checked(frame.Apply(partFrame.Apply(vertex.Origin * scale)), $"{what}: vertex {ids[i]} (physics polygon {key})");
                    Vector3 o = vertex.Origin;
                    exact[i] = frame.ApplyExact(partFrame.ApplyExact(new D3((double)o.X * scale.X, (double)o.Y * scale.Y, (double)o.Z * scale.Z)));
                }

                Polygons.Add((key, v, Geometry.NewellNormal(v, v[0])));
                Exact.Add(exact);
            }
        }

        public void AddCylinder(Vector3 origin, float radius, float height) =>
            Cylinders.Add((Checked(frame.Apply(origin), $"{name}: a cylinder"), radius, height));

        public (Vector3 Min, Vector3 Max) Bounds()
        {
            Vector3 min = new(float.MaxValue), max = new(float.MinValue);
            foreach ((_, Vector3[] v, _) in Polygons)
            {
                foreach (Vector3 p in v)
                {
                    (min, max) = (Vector3.Min(min, p), Vector3.Max(max, p));
                }
            }

            foreach ((Vector3 b, float r, float h) in Cylinders)
            {
                (min, max) = (Vector3.Min(min, b - new Vector3(r, r, 0f)), Vector3.Max(max, b + new Vector3(r, r, h)));
            }

            return min.X <= max.X ? (min, max) : (Vector3.Zero, Vector3.Zero);
        }

        private static Vector3 Checked(Vector3 p, string what)
        {
            const float limit = PhysicsConstants.MaxCellCoordinate;
            if (!(MathF.Abs(p.X) <= limit && MathF.Abs(p.Y) <= limit && MathF.Abs(p.Z) <= limit))
            {
                throw new ArgumentException($"{what} is placed at {p}, farther than {limit} m from the landblock.", "frame");
            }

            return p;
        }
    }
}
