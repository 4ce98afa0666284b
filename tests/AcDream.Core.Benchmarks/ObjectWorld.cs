using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Seeded object worlds (issue 11) for the object benchmarks and accuracy rows: the real objects of
/// <c>Fixtures/objects/</c> (cottage shell, small building, stair piece) and made-up trees (Setups
/// with one cylinder and one small box part), as a landblock's <see cref="LandBlockInfo"/>.
/// </summary>
internal static class ObjectWorld
{
    /// <summary>Objects per landblock in the benchmark world.</summary>
    public const int ObjectCount = 200;

    public const int Buildings = 5;

    /// <summary>Staircases of <see cref="StairPieces"/> stair pieces each.</summary>
    public const int Staircases = 3;

    public const int StairPieces = 5;

    public const int Trees = ObjectCount - Buildings - (Staircases * StairPieces);

    /// <summary>The objects stand at x ≥ this (landblock-local metres); the west of it is open ground.</summary>
    public const float WestEdge = 100f;

    /// <summary>The trunk part of every tree: a 0.6 m square box 2 m tall (six outward quads; its top is a floor).</summary>
    public const uint TrunkId = 0x01FF0001;

    /// <summary>The first of the four tree Setups (0x02FF0001..4), differing in cylinder radius and height.</summary>
    public const uint FirstTreeId = 0x02FF0001;

    /// <summary>The real objects by id, read from the fixtures (the 4 GfxObjs) plus the trunk.</summary>
    public static Dictionary<uint, GfxObj> GfxObjs()
    {
        string folder = Path.Combine(AppContext.BaseDirectory, "Fixtures", "objects");
        var result = new Dictionary<uint, GfxObj>();
        foreach (string path in Directory.GetFiles(folder, "0x*.json"))
        {
            GfxObj g = ObjectFixtureReader.Read(File.ReadAllText(path), path);
            result.Add(g.Id, g);
        }

        result.Add(TrunkId, Box(TrunkId, 0.3f, 2f));
        return result;
    }

    /// <summary>Four trees: one trunk part at identity, one cylinder of radius 0.3–0.6 m and height 4–10 m.</summary>
    public static Dictionary<uint, Setup> Setups()
    {
        var result = new Dictionary<uint, Setup>();
        for (uint k = 0; k < 4; k++)
        {
            result.Add(FirstTreeId + k, new Setup
            {
                Id = FirstTreeId + k,
                NumParts = 1,
                Parts = [TrunkId],
                CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = 0.3f + (0.1f * k), Height = 4f + (2f * k) }],
                Height = 4f + (2f * k),
                Radius = 0.3f + (0.1f * k),
            });
        }

        return result;
    }

    /// <summary>
    /// The benchmark landblock's object list, from <paramref name="random"/>: five building shells (the
    /// cottage shell and the small building alternately, random yaw), three staircases of five real stair
    /// pieces (random yaw), and the rest trees; all at x ≥ <see cref="WestEdge"/>, standing on the terrain,
    /// their footprints apart (buildings 24 m, staircases 6 m, trees 2 m from centre to centre at least).
    /// </summary>
    public static LandBlockInfo Info(Random random, TerrainSurface terrain)
    {
        var info = new LandBlockInfo { Id = World.Holtburg - 1 };
        var taken = new List<(Vector2 At, float Radius)>();
        for (int i = 0; i < Buildings; i++)
        {
            (Vector2 at, float yaw) = Free(random, taken, 12f, 180f);
            info.Buildings.Add(new BuildingInfo
            {
                ModelId = i % 2 == 0 ? ObjectPlacements.CottageShell : ObjectPlacements.SmallBuilding,
                Frame = Placed(at, terrain.SampleZ(at.X, at.Y), yaw),
            });
        }

        for (int s = 0; s < Staircases; s++)
        {
            (Vector2 at, float yaw) = Free(random, taken, 3f, 188f);
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw + (MathF.PI / 2f));
            Vector3 run = Vector3.Transform(new Vector3(0.5f, 0f, 0f), q) + new Vector3(0f, 0f, 0.4f);
            var origin = new Vector3(at, terrain.SampleZ(at.X, at.Y) - 0.2f) - (2f * run);
            for (int k = 0; k < StairPieces; k++)
            {
                info.Objects.Add(new Stab { Id = ObjectPlacements.StairPiece, Frame = new Frame { Origin = origin + (k * run), Orientation = q } });
            }
        }

        for (int t = 0; t < Trees; t++)
        {
            (Vector2 at, float yaw) = Free(random, taken, 1f, 190f);
            info.Objects.Add(new Stab { Id = FirstTreeId + (uint)random.Next(4), Frame = Placed(at, terrain.SampleZ(at.X, at.Y), yaw) });
        }

        return info;
    }

    /// <summary>The ObjectSurfaces of <paramref name="info"/> (outdoors), as the engine builds them.</summary>
    public static List<ObjectSurface> Surfaces(LandBlockInfo info, Dictionary<uint, GfxObj> gfxObjs, Dictionary<uint, Setup> setups) =>
        ObjectSurface.FromLandblock(World.Holtburg, info, [], gfxObjs, setups);

    /// <summary>The horizontal distance from <paramref name="p"/> to the nearest object's bounding box (0 inside one).</summary>
    public static float DistanceToObjects(IEnumerable<ObjectSurface> objects, Vector2 p)
    {
        float best = float.MaxValue;
        foreach (ObjectSurface o in objects)
        {
            float dx = MathF.Max(0f, MathF.Max(o.BoundsMin.X - p.X, p.X - o.BoundsMax.X));
            float dy = MathF.Max(0f, MathF.Max(o.BoundsMin.Y - p.Y, p.Y - o.BoundsMax.Y));
            best = MathF.Min(best, MathF.Sqrt((dx * dx) + (dy * dy)));
        }

        return best;
    }

    private static Frame Placed(Vector2 at, float z, float yaw) =>
        new() { Origin = new Vector3(at, z), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw) };

    /// <summary>A random point in x [<see cref="WestEdge"/> + radius, maxX], y [radius, 192 − radius], its circle of <paramref name="radius"/> apart from every one taken; and a random yaw.</summary>
    private static (Vector2 At, float Yaw) Free(Random random, List<(Vector2 At, float Radius)> taken, float radius, float maxX)
    {
        for (int tries = 0; tries < 100_000; tries++)
        {
            float x = WestEdge + radius + (random.NextSingle() * (maxX - WestEdge - radius));
            float y = radius + (random.NextSingle() * (192f - (2f * radius)));
            var at = new Vector2(x, y);
            float yaw = random.NextSingle() * 2f * MathF.PI;
            if (taken.TrueForAll(o => Vector2.Distance(o.At, at) >= o.Radius + radius))
            {
                taken.Add((at, radius));
                return (at, yaw);
            }
        }

        throw new InvalidOperationException("No free place for an object.");
    }

    /// <summary>An axis-aligned box GfxObj: [−h, h]² × [0, height], six quads wound outward.</summary>
    private static GfxObj Box(uint id, float h, float height)
    {
        var g = new GfxObj { Id = id, Flags = GfxObjFlags.HasPhysics };
        Vector3[] corners =
        [
            new(-h, -h, 0), new(h, -h, 0), new(h, h, 0), new(-h, h, 0),
            new(-h, -h, height), new(h, -h, height), new(h, h, height), new(-h, h, height),
        ];
        for (ushort i = 0; i < corners.Length; i++)
        {
            g.VertexArray.Vertices.Add(i, new SWVertex { Origin = corners[i] });
        }

        short[][] faces =
        [
            [0, 3, 2, 1], // bottom, down
            [4, 5, 6, 7], // top, up
            [0, 1, 5, 4], // −y
            [1, 2, 6, 5], // +x
            [2, 3, 7, 6], // +y
            [3, 0, 4, 7], // −x
        ];
        for (ushort f = 0; f < faces.Length; f++)
        {
            g.PhysicsPolygons.Add(f, new Polygon { VertexIds = [.. faces[f]] });
        }

        return g;
    }
}
