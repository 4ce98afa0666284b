using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Casts grazing the placed polygons of objects, against <see cref="CastReference"/> with the polygons placed exactly
/// (in double precision, from the dat's float vertices and the placement's float frame): no allowance for float-rounded
/// geometry. At 1° a surface off by 7.6e-6 m (the rounding of a coordinate near 150 m) moves the contact 4.4e-4 m along
/// the path; a cast's contact must be within 1e-4 m of the exact one for its inputs at any incidence down to 1°, over
/// paths up to 200 m, in both world frames.
/// </summary>
public class CastGrazingObjectTests(ITestOutputHelper output)
{
    /// <summary>Holtburg as seen from outdoors (the ground, the shells, the cells' walls), its real geometry placed exactly.</summary>
    private static CastScene Scene(string frame)
    {
        CastScene outdoors = CastWorlds.HoltburgOutdoors(frame);
        return new CastScene(outdoors.Engine, frame, TestData.Holtburg, outdoors.Shapes); // (GeometryRounding 0)
    }

    /// <summary>The small building's physics polygons, placed exactly, by key: its walls and floors (the plinth, its ramp, the roof).</summary>
    private static SortedDictionary<ushort, V3[]> SmallBuildingPolygons()
    {
        GfxObj model = RealObjects.GfxObjs[ObjectPlacements.SmallBuilding];
        Frame frame = ObjectPlacements.SmallBuildingShell().Frame;
        var result = new SortedDictionary<ushort, V3[]>();
        foreach ((ushort key, AcDream.Core.Dat.Polygon polygon) in model.PhysicsPolygons)
        {
            result[key] = [.. polygon.VertexIds.Select(i => V3.Of(ReferenceBody.Place(frame, model.VertexArray.Vertices[(ushort)i].Origin)))];
        }

        return result;
    }

    /// <summary>
    /// A segment of <paramref name="length"/> metres meeting <paramref name="target"/> on a polygon of unit normal
    /// <paramref name="n"/> from its side at <paramref name="degrees"/> to its plane, along the plane's direction
    /// <paramref name="along"/>, the target at fraction <paramref name="at"/>.
    /// </summary>
    private static (V3 From, V3 To) Grazing(V3 target, V3 n, V3 along, double degrees, double length, double at)
    {
        double a = degrees * Math.PI / 180;
        V3 w = (along * Math.Cos(a)) - (n * Math.Sin(a));
        return (target - (w * (length * at)), target + (w * (length * (1 - at))));
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_ray_grazing_the_small_buildings_ramp_at_1_44_degrees_meets_it_where_the_exact_polygon_is(string frame)
    {
        // Polygon 48 of 0x01000F69, met 32.8 m along a ray at 1.44° to it, at fraction 0.648, from above its plane.
        CastScene scene = Scene(frame);
        V3[] ramp = SmallBuildingPolygons()[48];
        V3 n = UnitNormal(ramp);
        n = n.Z < 0 ? -n : n;
        V3 centre = (ramp[0] + ramp[1] + ramp[2]) * (1.0 / 3);
        var worst = new Deviations(frame);
        foreach (V3 corner in ramp)
        {
            V3 target = centre + ((corner - centre) * 0.9); // near each corner, where the float plane strays most
            foreach (double azimuth in new[] { 0.0, 0.7, 1.9, 3.3, 4.4, 5.6 })
            {
                var flat = new V3(Math.Cos(azimuth), Math.Sin(azimuth), 0);
                V3 along = flat - (n * V3.Dot(flat, n));
                along *= 1.0 / along.Length;
                (V3 a, V3 b) = Grazing(target, n, along, 1.44, 32.8, 0.648);
                Vector3 from = scene.World(a), to = scene.World(b);
                CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(0f));
                scene.Tally(hit, scene.Expected(from, to, 0f), from, to, 0f, worst, $"polygon 48 at 1.44°, near {corner}, azimuth {azimuth}");
                (hit.Kind, hit.Id).Should().Be((SurfaceKind.ObjectFloor, ObjectPlacements.SmallBuilding), "a building's walkable polygon is a floor");
            }
        }

        output.WriteLine(worst.ToString());
        worst.Failures.Should().BeEmpty(worst.FailureReport());
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_grazing_the_small_buildings_polygons_at_1_to_5_degrees_over_up_to_200_m_meet_them_exactly(string frame)
    {
        // Every polygon of the building at least 0.5 m across, at a point well inside it, from the side its normal faces
        // (outward); each segment kept only if both ends are over the loaded land (Holtburg and its south neighbour).
        CastScene scene = Scene(frame);
        var random = new Random(29);
        var worst = new Deviations(frame);
        int building = 0, casts = 0;
        foreach ((ushort key, V3[] polygon) in SmallBuildingPolygons())
        {
            V3 n = UnitNormal(polygon);
            if (n == default || polygon.Max(p => (p - polygon[0]).Length) < 0.5)
            {
                continue;
            }

            foreach (double degrees in new[] { 1.0, 1.44, 2.5, 5.0 })
            {
                double length = new[] { 32.8, 100.0, 200.0 }[random.Next(3)];
                float r = new[] { 0f, 0f, 0.1f, 0.3f }[random.Next(4)];
                double u = random.NextDouble(), v = random.NextDouble() * (1 - u);
                int i = 1 + random.Next(polygon.Length - 2);
                V3 c = UnitMean(polygon);
                V3 target = c + ((((polygon[i] - c) * u) + ((polygon[i + 1] - c) * v)) * 0.8);
                V3 along = V3.Cross(n, new V3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                along *= 1.0 / along.Length;
                (V3 a, V3 b) = Grazing(target + (n * r), n, along, degrees, length, 0.2 + (random.NextDouble() * 0.6));
                if (!Loaded(a) || !Loaded(b) || a.Z < 94 + r + 0.01 || scene.Clearance(a) < r + 0.01)
                {
                    continue;
                }

                Vector3 from = scene.World(a), to = scene.World(b);
                CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(r));
                scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, $"polygon {key} at {degrees}° over {length} m, r {r}, aimed at {target}");
                building += hit.Id == ObjectPlacements.SmallBuilding ? 1 : 0;
                casts++;
            }
        }

        output.WriteLine($"{worst}; {building} of {casts} met the building");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        building.Should().BeGreaterThan(casts / 3);

        static bool Loaded(V3 p) => p.X > 0.5 && p.X < 191.5 && p.Y > -191.5 && p.Y < 191.5;

        static V3 UnitMean(V3[] p) => p.Aggregate(default(V3), (s, q) => s + q) * (1.0 / p.Length);
    }
}
