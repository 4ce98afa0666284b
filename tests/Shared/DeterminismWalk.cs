using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced).

/// <summary>
/// A seeded walk among objects whose every answer is hashed, bit for bit: run in two processes (one with
/// <c>DOTNET_EnableHWIntrinsic=0</c>, one without) the hashes must agree, which is what a client and a server
/// on different processors need. Four landblocks of rolling terrain at the far corner of the world, each with
/// real buildings and stair pieces, made-up trees and low platforms at random (some reaching over the
/// seams); walks toward them of 5 cm to 4 m per move with the point, the body and
/// <see cref="MovementOptions.Player"/>, in the global frame and one centred far away; after every move a chase
/// camera's cast (a 0.3 m sphere) behind the mover and a 40 m ray ahead of it.
/// </summary>
internal static class DeterminismWalk
{
    private static readonly uint[] Landblocks = [0xFDFDFFFFu, 0xFEFDFFFFu, 0xFDFEFFFFu, 0xFEFEFFFFu];

    /// <summary>What a walk did: the hash of every answer, how many there were, how many slid, stood on an object or were refused, and how many casts met something (camera, ray).</summary>
    public readonly record struct Summary(ulong Hash, int Answers, int Slid, int OnObjects, int Refused, int CameraHits, int RayHits);

    /// <summary>
    /// Runs the walk with the real objects <paramref name="gfxObjs"/> (the cottage shell 0x01000A2B, the small
    /// building 0x01000F69, the stair piece 0x01000AC5 and its end 0x01000ACA).
    /// </summary>
    public static Summary Run(IReadOnlyDictionary<uint, GfxObj> gfxObjs, int walks = 30, int moves = 40)
    {
        ulong hash = 14695981039346656037ul;
        int answers = 0, slid = 0, onObjects = 0, refused = 0, cameraHits = 0, rayHits = 0;
        foreach (bool global in new[] { true, false })
        {
            foreach (MovementOptions options in new[] { MovementOptions.Literal, new MovementOptions { Body = MoverBody.Player }, MovementOptions.Player })
            {
                var random = new Random(answers + 5);
                PhysicsEngine engine = global ? new PhysicsEngine() : new PhysicsEngine(0x0101FFFFu);
                var targets = new List<(uint Landblock, Vector3 Local)>();
                foreach (uint landblock in Landblocks)
                {
                    var terrain = new TerrainSurface(Heights(landblock), Table, landblock);
                    List<ObjectSurface> objects = Objects(random, terrain, gfxObjs);
                    engine.AddLandblock(landblock, terrain, [], objects);
                    targets.AddRange(objects.Select(o => (landblock, (o.BoundsMin + o.BoundsMax) / 2f)));
                }

                Vector3 corner = engine.GetLandblockOrigin(Landblocks[0]);
                for (int walk = 0; walk < walks; walk++)
                {
                    (uint landblock, Vector3 local) = targets[random.Next(targets.Count)];
                    Vector3 target = engine.GetLandblockOrigin(landblock) + local;
                    var start = Vector3.Clamp(
                        target + new Vector3((float)((random.NextDouble() * 16) - 8), (float)((random.NextDouble() * 16) - 8), 0f),
                        corner + new Vector3(1f, 1f, 0f), corner + new Vector3(383f, 383f, 0f));
                    uint cell = engine.LandblockAt(start) & 0xFFFF0000;
                    engine.TryGetGround(start, cell, out float z, out _);
                    ResolveResult at = engine.Resolve(start with { Z = z }, cell, Vector3.Zero, 0.6f, options);
                    for (int m = 0; m < moves; m++)
                    {
                        float heading = MathF.Atan2(target.Y - at.Position.Y, target.X - at.Position.X) + (float)((random.NextDouble() - 0.5) * 1.5);
                        float length = 0.05f + (float)(random.NextDouble() * (random.Next(6) == 0 ? 4 : 0.6));
                        // With vertical motion a jump now and then, and a fall by the delta while in the air.
                        float dz = !options.Vertical ? 0f : !at.IsOnGround ? -0.3f : random.Next(8) == 0 ? 0.4f : 0f;
                        ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, dz), 0.6f, options);
                        hash = Mix(hash, r);
                        answers++;
                        slid += r.Outcome == ResolveOutcome.Slid ? 1 : 0;
                        refused += r.IsRefused ? 1 : 0;
                        if (r.Outcome == ResolveOutcome.Held)
                        {
                            break;
                        }

                        // The chase camera's cast behind the mover and a pointer's ray ahead and down (every shape a cast meets, in double).
                        var forward = new Vector3(MathF.Cos(heading), MathF.Sin(heading), 0f);
                        Vector3 pivot = r.Position + new Vector3(0f, 0f, 1.5f);
                        CastHit eye = engine.Cast(pivot, r.CellId, pivot - (forward * 2.5f) + new Vector3(0f, 0f, 0.75f), new CastOptions(0.3f));
                        CastHit ray = engine.Cast(pivot, r.CellId, pivot + (forward * 40f) - new Vector3(0f, 0f, 4f), new CastOptions(0f));
                        hash = Mix(Mix(hash, eye), ray);
                        (cameraHits, rayHits) = (cameraHits + (eye.Hit ? 1 : 0), rayHits + (ray.Hit ? 1 : 0));

                        bool found = engine.TryGetGround(r.Position, r.CellId, 0.6f, out float ground, out Vector3 normal, out uint objectId);
                        hash = Mix(Mix(hash, BitConverter.SingleToUInt32Bits(ground)), BitConverter.SingleToUInt32Bits(normal.X) ^ BitConverter.SingleToUInt32Bits(normal.Y) ^ objectId);
                        onObjects += found && objectId != 0 && r.IsOnGround ? 1 : 0;
                        at = r.IsOnGround || !found || options.Vertical ? r : r with { Position = r.Position with { Z = ground } };
                    }
                }
            }
        }

        return new Summary(hash, answers, slid, onObjects, refused, cameraHits, rayHits);
    }

    /// <summary>Heights in metres per table index: a quarter metre.</summary>
    private static readonly float[] Table = Enumerable.Range(0, 256).Select(i => 30f + (0.25f * i)).ToArray();

    /// <summary>Rolling heights shared along every seam (a function of the global vertex).</summary>
    private static byte[] Heights(uint landblock)
    {
        int x0 = CellIds.LandblockX(landblock) * 8, y0 = CellIds.LandblockY(landblock) * 8;
        var heights = new byte[81];
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                heights[(x * 9) + y] = (byte)(40 + (int)(12 * Math.Sin((x0 + x) * 0.9)) + (int)(10 * Math.Cos((y0 + y) * 0.7)));
            }
        }

        return heights;
    }

    /// <summary>Two buildings, stair pieces, trees and low platforms at random, some within 8 m of a seam.</summary>
    private static List<ObjectSurface> Objects(Random random, TerrainSurface terrain, IReadOnlyDictionary<uint, GfxObj> gfxObjs)
    {
        var objects = new List<ObjectSurface>();
        var trunk = new GfxObj { Id = 0x01000001 };
        var tree = new Setup { Id = 0x02000001, NumParts = 1, Parts = [trunk.Id], CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = 0.4f, Height = 6f }] };
        var parts = new Dictionary<uint, GfxObj> { [trunk.Id] = trunk };
        uint[] models = [0x01000F69, 0x01000F69, 0x01000A2B, 0x01000AC5, 0x01000AC5, 0x01000ACA];
        for (int i = 0; i < 24; i++)
        {
            float x = i % 4 == 0 ? (random.Next(2) == 0 ? 2f : 186f) + (float)(random.NextDouble() * 4) : 12f + (float)(random.NextDouble() * 168);
            float y = i % 5 == 0 ? (random.Next(2) == 0 ? 2f : 186f) + (float)(random.NextDouble() * 4) : 12f + (float)(random.NextDouble() * 168);
            float yaw = (float)(random.NextDouble() * 2 * Math.PI);
            var frame = new Frame { Origin = new Vector3(x, y, terrain.SampleZ(x, y)), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw) };
            if (i < 11)
            {
                frame.Origin += new Vector3(0f, 0f, (float)((random.NextDouble() * 0.6) - 0.4));
                objects.Add(new ObjectSurface(gfxObjs[models[i % models.Length]], frame, 0));
            }
            else if (i < 14)
            {
                objects.Add(new ObjectSurface(tree, parts, frame, 0));
            }
            else
            {
                float half = 1f + (float)random.NextDouble();
                frame.Origin += new Vector3(0f, 0f, 0.2f + (float)(random.NextDouble() * 0.8));
                objects.Add(new ObjectSurface(Platform(0x01000500u + (uint)i, half, walls: i % 2 == 1), frame, 0));
            }
        }

        return objects;
    }

    /// <summary>Adds <paramref name="polygons"/> (vertex loops, object-local, each with its own vertices) to <paramref name="gfx"/> as physics polygons; returns it.</summary>
    public static GfxObj AddPhysicsPolygons(GfxObj gfx, Vector3[][] polygons)
    {
        ushort next = 0;
        for (int p = 0; p < polygons.Length; p++)
        {
            var ids = new List<short>();
            foreach (Vector3 v in polygons[p])
            {
                gfx.VertexArray.Vertices[next] = new SWVertex { Origin = v };
                ids.Add((short)next++);
            }

            gfx.PhysicsPolygons[(ushort)p] = new Polygon { VertexIds = ids };
        }

        return gfx;
    }

    /// <summary>A square floor of half-side <paramref name="half"/> at z 0, with 2 m sides below it or none.</summary>
    private static GfxObj Platform(uint id, float half, bool walls)
    {
        Vector3[][] polygons = walls
            ? [Square(half), Side(-half, -half, half, -half), Side(half, -half, half, half), Side(half, half, -half, half), Side(-half, half, -half, -half)]
            : [Square(half)];
        return AddPhysicsPolygons(new GfxObj { Id = id }, polygons);

        static Vector3[] Square(float h) => [new(-h, -h, 0f), new(h, -h, 0f), new(h, h, 0f), new(-h, h, 0f)];

        static Vector3[] Side(float x0, float y0, float x1, float y1) => [new(x0, y0, -2f), new(x1, y1, -2f), new(x1, y1, 0f), new(x0, y0, 0f)];
    }

    private static ulong Mix(ulong hash, in ResolveResult r)
    {
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(r.Position.X));
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(r.Position.Y));
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(r.Position.Z));
        hash = Mix(hash, r.CellId);
        hash = Mix(hash, (uint)r.Outcome | (r.IsOnGround ? 0x100u : 0u));
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(r.SurfaceNormal.X));
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(r.SurfaceNormal.Y));
        return Mix(hash, BitConverter.SingleToUInt32Bits(r.SurfaceNormal.Z));
    }

    private static ulong Mix(ulong hash, in CastHit h)
    {
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(h.Fraction) ^ (uint)h.Kind ^ h.Id ^ h.CellId);
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(h.Position.X) ^ BitConverter.SingleToUInt32Bits(h.Point.Y));
        hash = Mix(hash, BitConverter.SingleToUInt32Bits(h.Position.Z) ^ BitConverter.SingleToUInt32Bits(h.Normal.X));
        return Mix(hash, BitConverter.SingleToUInt32Bits(h.Normal.Y) ^ BitConverter.SingleToUInt32Bits(h.Normal.Z));
    }

    private static ulong Mix(ulong hash, uint value)
    {
        for (int i = 0; i < 4; i++)
        {
            hash = (hash ^ ((value >> (8 * i)) & 0xFF)) * 1099511628211ul;
        }

        return hash;
    }
}
