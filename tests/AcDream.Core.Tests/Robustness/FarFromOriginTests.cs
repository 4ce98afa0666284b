using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Landblocks at the corners of the world in both world frames give the answers of the
/// landblock-local frame for the same move to the end point rounded to the world frame: Z and cell
/// ids bit for bit, world XY rounded once; and resolving an answer again in place returns it.
/// </summary>
public class FarFromOriginTests
{
    public static TheoryData<uint, string> Corners() => new()
    {
        { 0x0000FFFFu, "global" }, { 0x0000FFFFu, "centred here" }, { 0x0000FFFFu, "centred far" },
        { 0xFEFEFFFFu, "global" }, { 0xFEFEFFFFu, "centred here" }, { 0xFEFEFFFFu, "centred far" },
        { 0xFE00FFFFu, "global" }, { 0x00FEFFFFu, "centred far" },
    };

    private const float FloorZ = 1.88f;

    /// <summary>
    /// The landblock (hills 0..2.8 m, flat 1.68 m in outdoor cell (2, 0)), its south neighbour when in
    /// the world (flat 1.68 m), and a room rotated 180° with a slightly non-unit quaternion whose floor
    /// (1.88 m, x 56..64, y −3.5..2) reaches past the south seam.
    /// </summary>
    private static PhysicsEngine Build(uint landblock, string frame)
    {
        uint far = (0xFEFE0000u - (landblock & 0xFFFF0000u)) | 0xFFFFu; // the opposite corner
        var engine = frame switch
        {
            "global" => new PhysicsEngine(),
            "centred here" => new PhysicsEngine(landblock),
            _ => new PhysicsEngine(far),
        };
        byte[] heights = Heights((x, y) => x is 2 or 3 && y <= 1 ? 3 : ((x * 7) + (y * 3)) % 5);
        engine.AddLandblock(landblock, new TerrainSurface(heights, NonLinearTable(), landblock), [Room(landblock)]);
        if ((landblock & 0x00FF0000u) != 0)
        {
            uint south = landblock - 0x00010000u;
            engine.AddLandblock(south, new TerrainSurface(FlatHeights(3), NonLinearTable(), south), []);
        }

        return engine;
    }

    private static CellSurface Room(uint landblock) =>
        new CellBuilder((landblock & 0xFFFF0000u) | 0x0100u, new Vector3(60, 0.5f, FloorZ - 0.25f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI) * 1.0005f)
            .Floor(-4, -1.5f, 4, 4, 0.25f)
            .Build();

    [Theory]
    [MemberData(nameof(Corners))]
    public void Resolve_CornerLandblocksInEveryFrame_SameAnswersAsLandblockLocal(uint landblock, string frame)
    {
        PhysicsEngine local = Build(landblock, "centred here");
        PhysicsEngine engine = Build(landblock, frame);
        Vector3 offset = engine.GetLandblockOrigin(landblock);
        var random = new Random(23);
        uint prefix = landblock & 0xFFFF0000u;
        for (int n = 0; n < 3000; n++)
        {
            // Start positions on a 1/256 m grid are exact in every frame (the far corner's float spacing is 1/256 m).
            var start = new Vector2(random.Next(0, 192 * 256) / 256f, random.Next(0, 192 * 256) / 256f);
            bool indoor = n % 4 == 0;
            if (indoor)
            {
                start = new Vector2(random.Next(57 * 256, 63 * 256) / 256f, random.Next(-3 * 256, 2 * 256) / 256f);
            }

            uint cell = indoor ? prefix | 0x0100u : prefix | (uint)random.Next(1, 0x41);
            var delta = new Vector3(Gen.Range(random, -3, 3), Gen.Range(random, -3, 3), 0);
            float z = Gen.Range(random, -5, 1500);
            // The engine computes its answer at the end point it can return: the local end point rounded
            // to the world frame's float spacing. The landblock-local frame gets the same move to it.
            Vector2 end = start + new Vector2(delta.X, delta.Y);
            Vector2 rounded = (new Vector2(offset.X, offset.Y) + end) - new Vector2(offset.X, offset.Y);
            ResolveResult expected = local.Resolve(new Vector3(start, z), cell, new Vector3(rounded - start, 0), 2000f);
            ResolveResult actual = engine.Resolve(new Vector3(start.X + offset.X, start.Y + offset.Y, z), cell, delta, 2000f);
            string what = $"case {n}: {frame}, local start {start:R} z {z:R} in 0x{cell:X8} by {delta:R}; landblock-local answer {expected}";

            actual.CellId.Should().Be(expected.CellId, what);
            actual.IsOnGround.Should().Be(expected.IsOnGround, what);
            actual.Position.Z.Should().Be(expected.Position.Z, $"{what}: Z is computed landblock-locally, bit for bit");
            Vector3 neighbourOffset = engine.GetLandblockOrigin(expected.CellId) - local.GetLandblockOrigin(expected.CellId);
            actual.Position.X.Should().Be(expected.Position.X + neighbourOffset.X, $"{what}: world X is the local answer rounded once");
            actual.Position.Y.Should().Be(expected.Position.Y + neighbourOffset.Y, what);

            // And resolving it again in place returns it bit for bit: the next frame stands where this one
            // ended. (Not for a refused mover in mid-air: the literal engine snaps any accepted move to the ground.)
            if (actual.IsOnGround)
            {
                ResolveResult again = engine.Resolve(actual.Position, actual.CellId, Vector3.Zero, 2000f);
                (again.Position, again.CellId, again.IsOnGround).Should().Be((actual.Position, actual.CellId, actual.IsOnGround), $"{what}: fixed point");
            }
        }
    }

    [Theory]
    [InlineData(0x0000FFFFu)]
    [InlineData(0xFEFEFFFFu)]
    public void Resolve_CellFloorPastTheSouthSeamAtWorldEdge_FoundFromInsideNeverFromOutside(uint landblock)
    {
        foreach (string frame in new[] { "global", "centred here", "centred far" })
        {
            PhysicsEngine engine = Build(landblock, frame);
            Vector3 offset = engine.GetLandblockOrigin(landblock);
            uint prefix = landblock & 0xFFFF0000u, room = prefix | 0x0100u;

            // Inside the room, walking south across y = 0: still the room, on its floor at y −0.5 (local).
            ResolveResult inside = engine.Resolve(offset + new Vector3(60, 0.25f, FloorZ), room, new Vector3(0, -0.75f, 0), 0.5f);
            inside.CellId.Should().Be(room, frame);
            (inside.Position.Y - offset.Y).Should().BeApproximately(-0.5f, 4e-3f, frame);
            inside.Position.Z.Should().BeApproximately(FloorZ, 1e-5f, frame);

            // Outdoors north of the room, stepping 0.2 m up onto its floor from its own landblock: entered.
            ResolveResult entry = engine.Resolve(offset + new Vector3(60, 3f, 1.68f), prefix, new Vector3(0, -1.5f, 0), 0.5f);
            entry.CellId.Should().Be(room, frame);
            entry.Position.Z.Should().BeApproximately(FloorZ, 1e-5f, frame);

            // Outdoors in the south neighbour over the room's footprint: terrain, never the room.
            if ((landblock & 0x00FF0000u) != 0)
            {
                ResolveResult outside = engine.Resolve(offset + new Vector3(60, -1f, 1.68f), prefix - 0x00010000u, new Vector3(-0.5f, 0, 0), 0.5f);
                (outside.CellId & 0xFFFF0000u).Should().Be(prefix - 0x00010000u, frame);
                (outside.CellId & 0xFFFF).Should().BeLessThan(0x100u, $"{frame}: the room belongs to the landblock north of the seam");
                outside.Position.Z.Should().Be(NonLinearTable()[3], frame);
            }
        }
    }
}
