using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>Degenerate polygons and rotations: never a NaN, a documented outcome for each.</summary>
public class GeometryTests
{
    private const uint CellId = 0xA9B40100u;

    private static CellSurface Cell(Vector3[] polygon) => new CellBuilder(CellId, new Vector3(100, 100, 10)).Physics(polygon).Build();

    /// <summary>Every query over a 0.25 m grid around the cell is null or a finite Z.</summary>
    private static void ExpectFiniteEverywhere(CellSurface cell, string what)
    {
        for (float x = 85f; x <= 115f; x += 0.25f)
        {
            for (float y = 85f; y <= 115f; y += 0.25f)
            {
                float? z = cell.SampleFloorZ(x, y);
                if (z is float value)
                {
                    float.IsFinite(value).Should().BeTrue($"{what} at ({x}, {y})");
                }
            }
        }
    }

    public static TheoryData<string, Vector3[]> NoFloor() => new()
    {
        { "zero area (all three at one point)", [new(1, 1, 0), new(1, 1, 0), new(1, 1, 0)] },
        { "collinear", [new(0, 0, 0), new(1, 1, 0), new(3, 3, 0), new(2, 2, 0)] },
        { "duplicated vertex only", [new(0, 0, 0), new(4, 0, 0), new(4, 0, 0)] },
        { "sliver 0.1 mm wide", [new(0, 0, 0), new(10, 0, 0), new(5, 0.0001f, 0)] },
        { "vertical wall", Wall(-5, 0, 5, 0, 0, 3) },
        { "ceiling (faces down)", Square(-5, -5, 5, 5, 3).Reverse().ToArray() },
        { "reversed winding floor", [new(0, 0, 0), new(0, 4, 0), new(4, 4, 0), new(4, 0, 0)] },
        { "steeper than FloorZ", [new(0, 0, 0), new(2, 0, 3), new(2, 2, 3), new(0, 2, 0)] },
        { "bow-tie (self-crossing, zero net area)", [new(0, 0, 0), new(4, 4, 0), new(4, 0, 0), new(0, 4, 0)] },
    };

    [Theory]
    [MemberData(nameof(NoFloor))]
    public void SampleFloorZ_DegeneratePolygon_IsNoFloorAndNeverNaN(string kind, Vector3[] polygon)
    {
        CellSurface cell = Cell(polygon);
        cell.HasFloor.Should().BeFalse(kind);
        ExpectFiniteEverywhere(cell, kind);
        cell.SampleFloorZ(101, 100).Should().BeNull(kind);
    }

    [Fact]
    public void SampleFloorZ_SliverThickerThanTolerance_IsAFloorWithinItsZRange()
    {
        // 0.5 mm wide, 10 m long, rising 3 m: a real (if thin) floor.
        CellSurface cell = Cell([new(0, 0, 0), new(10, 0, 3), new(5, 0.0005f, 1.5f)]);
        cell.HasFloor.Should().BeTrue();
        for (float x = 0f; x <= 10f; x += 0.125f)
        {
            // On its long edge everywhere, and across its middle where it is wider than 0.25 mm.
            foreach (float y in x is > 2.6f and < 7.4f ? new[] { 0f, 0.00025f } : new[] { 0f })
            {
                float? z = cell.SampleFloorZ(100 + x, 100 + y);
                z.Should().NotBeNull($"({x}, {y})");
                z!.Value.Should().BeInRange(10f, 13f).And.BeApproximately(10 + (0.3f * x), 1e-4f, $"({x}, {y})");
            }
        }
    }

    [Fact]
    public void SampleFloorZ_CollinearAndDuplicatedVerticesOnARamp_ZExactAlongTheEdges()
    {
        // A 10 m ramp rising 5 m whose south edge carries a collinear mid vertex and a duplicated vertex.
        // Before the fix the float placement turned (v0, mid, v2) into a sliver whose Z, near its
        // edge, was blended from the wrong vertices: millimetres to metres off, and topmost wins.
        Vector3[] ramp = [new(0, 0, 0), new(5, 0, 2.5f), new(5, 0, 2.5f), new(10, 0, 5), new(10, 4, 5), new(0, 4, 0)];
        foreach (float degrees in new[] { 0f, 33f, 90f, 180f, 271f })
        {
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);
            var origin = new Vector3(150.37f, 170.91f, 87.3f);
            CellSurface cell = new CellBuilder(CellId, origin, rotation).Physics(ramp).Build();
            for (float x = 0f; x <= 10f; x += 1f / 32)
            {
                foreach (float y in new[] { 0f, 0.0001f, 2f, 4f })
                {
                    Vector3 p = origin + Vector3.Transform(new Vector3(x, y, 0), rotation);
                    float? z = cell.SampleFloorZ(p.X, p.Y);
                    z.Should().NotBeNull($"{degrees}°, ramp-local ({x}, {y})");
                    z!.Value.Should().BeApproximately(origin.Z + (0.5f * x), 1e-4f, $"{degrees}°, ramp-local ({x}, {y})");
                }
            }
        }
    }

    [Fact]
    public void SampleFloorZ_NonPlanarQuad_EachFanTriangleIsItsOwnPlaneAndContinuous()
    {
        // A twisted quad (one corner raised 0.4 m): two fan triangles sharing the diagonal v0–v2.
        CellSurface cell = Cell([new(0, 0, 0), new(4, 0, 0), new(4, 4, 0), new(0, 4, 0.4f)]);
        cell.SampleFloorZ(103, 101)!.Value.Should().BeApproximately(10f, 1e-5f, "triangle (v0, v1, v2) is flat");
        cell.SampleFloorZ(101, 103)!.Value.Should().BeApproximately(10.2f, 1e-5f, "triangle (v0, v2, v3): z = 0.1 (y − x) + 0... at (1, 3) is 0.2");
        for (float t = 0f; t <= 4f; t += 0.0625f)
        {
            cell.SampleFloorZ(100 + t, 100 + t)!.Value.Should().BeApproximately(10f, 1e-5f, $"the shared diagonal at {t}");
        }
    }

    [Theory]
    [InlineData(5)]
    [InlineData(64)]
    [InlineData(1000)]
    public void SampleFloorZ_PolygonOfManyVertices_FloorEverywhereInside(int vertices)
    {
        // A regular n-gon of radius 8 on a plane tilted 0.2 along x.
        var polygon = new Vector3[vertices];
        for (int i = 0; i < vertices; i++)
        {
            double a = 2 * Math.PI * i / vertices;
            float x = (float)(8 * Math.Cos(a)), y = (float)(8 * Math.Sin(a));
            polygon[i] = new Vector3(x, y, 0.2f * x);
        }

        CellSurface cell = Cell(polygon);
        double inner = 8 * Math.Cos(Math.PI / vertices) - 1e-3; // the n-gon's inscribed radius
        var random = new Random(vertices);
        for (int n = 0; n < 2000; n++)
        {
            double r = inner * Math.Sqrt(random.NextDouble()), a = random.NextDouble() * 2 * Math.PI;
            float x = (float)(r * Math.Cos(a)), y = (float)(r * Math.Sin(a));
            float? z = cell.SampleFloorZ(100 + x, 100 + y);
            z.Should().NotBeNull($"{vertices}-gon at ({x}, {y})");
            z!.Value.Should().BeApproximately(10 + (0.2f * x), 1e-4f, $"{vertices}-gon at ({x}, {y})");
        }

        cell.SampleFloorZ(109, 100).Should().BeNull("outside the circumscribed circle");
    }

    [Fact]
    public void Portals_DegeneratePortalPolygon_ZeroNormalAndNeverCrossed()
    {
        // A collinear "doorway": zero area, so no plane to cross; the mover walks on its own floor.
        var builder = new CellBuilder(CellId).Floor(20, 20, 24, 24, 50);
        builder.Portal(0xFFFF, new Vector3(22, 22, 51), new(20, 21, 50), new(20, 22, 50), new(20, 23, 50));
        CellSurface room = builder.Build();
        room.Portals[0].PortalNormal.Should().Be(Vector3.Zero);
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(50f), [room]);
        var pos = new Vector3(20.3f, 22, 50);
        engine.Resolve(pos, CellId, new Vector3(-0.5f, 0, 0), 0.5f).Should().Be(new ResolveResult(pos, CellId, true) { Outcome = ResolveOutcome.Wall }, "no portal to pass: a wall");
        engine.Resolve(pos, CellId, new Vector3(0.5f, 0, 0), 0.5f).Position.X.Should().BeApproximately(20.8f, 1e-5f);
    }

    public static TheoryData<string, Quaternion> Rotations()
    {
        var data = new TheoryData<string, Quaternion>();
        foreach (float degrees in new[] { 0f, 90f, 180f, 270f, -90f, 17.3f, 123.456f, 359.99f })
        {
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);
            data.Add($"{degrees}°", q);
            data.Add($"{degrees}° × 0.999", q * 0.999f);
            data.Add($"{degrees}° × 1.001", q * 1.001f);
            data.Add($"{degrees}° negated", -q);
            data.Add($"{degrees}° with 1e-5 of tilt noise", new Quaternion(q.X + 1e-5f, q.Y - 1e-5f, q.Z, q.W));
        }

        data.Add("180° as stored (W = −4.37e-8)", new Quaternion(0, 0, 1, -4.371139e-8f));
        data.Add("90° scaled by 1e20", Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2) * 1e20f);
        data.Add("90° scaled by 1e-5", Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2) * 1e-5f);
        return data;
    }

    [Theory]
    [MemberData(nameof(Rotations))]
    public void SampleFloorZ_RotatedCell_FloorLandsWhereTheNormalisedRotationPutsIt(string name, Quaternion q)
    {
        // An L of two floors (2 × 6 m at z 0.5, and a 1 × 1 m step at z 0.9), placed at (100, 50, 20).
        var origin = new Vector3(100, 50, 20);
        CellSurface cell = new CellBuilder(CellId, origin, q).Floor(1, 0, 3, 6, 0.5f).Floor(3, 5, 4, 6, 0.9f).Build();

        // Where the rotation puts cell-local points, computed in double from the normalised quaternion.
        double n = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
        var unit = new Quaternion((float)(q.X / n), (float)(q.Y / n), (float)(q.Z / n), (float)(q.W / n));
        foreach ((Vector3 local, float? expected) in new (Vector3, float?)[]
        {
            (new(2, 3, 0), 20.5f), (new(1.01f, 0.01f, 0), 20.5f), (new(2.99f, 5.99f, 0), 20.5f), (new(3.5f, 5.5f, 0), 20.9f),
            (new(-2, 3, 0), null), (new(3.5f, 4.5f, 0), null), (new(2, 6.1f, 0), null),
        })
        {
            Vector3 p = origin + Vector3.Transform(local, unit);
            float? z = cell.SampleFloorZ(p.X, p.Y);
            if (expected is null)
            {
                z.Should().BeNull($"{name}: cell-local {local} is off the floor");
            }
            else
            {
                z.Should().NotBeNull($"{name}: cell-local {local}");
                z!.Value.Should().BeApproximately(expected.Value, 2e-4f, $"{name}: cell-local {local}");
            }
        }
    }
}
