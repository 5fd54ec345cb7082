<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<CityModel gml:id="cm1" xmlns:app="http://www.opengis.net/citygml/appearance/3.0" xmlns:brid="http://www.opengis.net/citygml/bridge/3.0" xmlns:bldg="http://www.opengis.net/citygml/building/3.0" xmlns:frn="http://www.opengis.net/citygml/cityfurniture/3.0" xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/3.0" xmlns:con="http://www.opengis.net/citygml/construction/3.0" xmlns:pcl="http://www.opengis.net/citygml/pointcloud/3.0" xmlns:core="http://www.opengis.net/citygml/3.0" xmlns:dyn="http://www.opengis.net/citygml/dynamizer/3.0" xmlns:gen="http://www.opengis.net/citygml/generics/3.0" xmlns:luse="http://www.opengis.net/citygml/landuse/3.0" xmlns:dem="http://www.opengis.net/citygml/relief/3.0" xmlns:tran="http://www.opengis.net/citygml/transportation/3.0" xmlns:tun="http://www.opengis.net/citygml/tunnel/3.0" xmlns:veg="http://www.opengis.net/citygml/vegetation/3.0" xmlns:vers="http://www.opengis.net/citygml/versioning/3.0" xmlns:wtr="http://www.opengis.net/citygml/waterbody/3.0" xmlns:tsml="http://www.opengis.net/tsml/1.0" xmlns:sos="http://www.opengis.net/sos/2.0" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:ade="http://www.3dcitydb.org/citygml-ade/3.0/citygml/1.0" xmlns="http://www.opengis.net/citygml/3.0" xsi:schemaLocation="http://www.opengis.net/citygml/appearance/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/appearance.xsd http://www.opengis.net/citygml/bridge/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/bridge.xsd http://www.opengis.net/citygml/building/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/building.xsd http://www.opengis.net/citygml/cityfurniture/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityFurniture.xsd http://www.opengis.net/citygml/cityobjectgroup/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityObjectGroup.xsd http://www.opengis.net/citygml/construction/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/construction.xsd http://www.opengis.net/citygml/pointcloud/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/pointCloud.xsd http://www.opengis.net/citygml/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/cityGMLBase.xsd http://www.opengis.net/citygml/dynamizer/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/dynamizer.xsd http://www.opengis.net/citygml/generics/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/generics.xsd http://www.opengis.net/citygml/landuse/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/landUse.xsd http://www.opengis.net/citygml/relief/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/relief.xsd http://www.opengis.net/citygml/transportation/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/transportation.xsd http://www.opengis.net/citygml/tunnel/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/tunnel.xsd http://www.opengis.net/citygml/vegetation/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/vegetation.xsd http://www.opengis.net/citygml/versioning/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/versioning.xsd http://www.opengis.net/citygml/waterbody/3.0 http://www.3dcitydb.org/citygml3/2019-06-05/xsds/waterBody.xsd http://www.opengis.net/tsml/1.0 http://schemas.opengis.net/tsml/1.0/timeseriesML.xsd http://www.opengis.net/sos/2.0 http://schemas.opengis.net/sos/2.0/sosGetObservation.xsd urn:oasis:names:tc:ciq:xsdschema:xAL:2.0 http://schemas.opengis.net/citygml/xAL/xAL.xsd">
    <cityObjectMember>
        <bldg:Building gml:id="BLDG_0003000b001e15b2">
            <gml:boundedBy>
                <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG:6.12:25833,crs:EPSG:6.12:5783" srsDimension="3">
                    <gml:lowerCorner>388662.065952822 5818794.94363753 33.0499992370605</gml:lowerCorner>
                    <gml:upperCorner>388694.55459302 5818814.54570493 37.1355109214783</gml:upperCorner>
                </gml:Envelope>
            </gml:boundedBy>
            <creationDate>2015-04-22T00:00:00</creationDate>
            <externalReference>
                <ExternalReference>
                    <targetResource>urn:adv:oid:0003000b001e15b2</targetResource>
                    <informationSystem>LOCATION</informationSystem>
                </ExternalReference>
            </externalReference>
            <appearance>
                <app:Appearance gml:id="UUID_74b84c57-1f92-4e6a-849b-fdd238f48379">
                    <app:theme>Eignung Solarthermie</app:theme>
                    <app:surfaceData>
                        <app:ParameterizedTexture gml:id="UUID_60ccf25e-f370-4df4-a1d0-62414138f95a">
                            <app:imageURI>appearance/tex5284715.jpg</app:imageURI>
                            <app:mimeType>image/jpeg</app:mimeType>
                            <app:textureType>unknown</app:textureType>
                            <app:wrapMode>wrap</app:wrapMode>
                            <app:borderColor>1.0 1.0 1.0 1.0</app:borderColor>
                            <app:textureParameterization>
                                <app:TextureAssociation>
                                    <app:uri>#GEOM_6946743</app:uri>
                                    <app:textureParameterization>
                                        <app:TexCoordList>
                                            <app:textureCoordinates>0.999851 0.988286 0.829853 0.99897 6.8E-5 0.007396 0.170888 3.01E-4 0.999851 0.988286</app:textureCoordinates>
                                            <app:ring>#GEOM_6946743_0_</app:ring>
                                        </app:TexCoordList>
                                    </app:textureParameterization>
                                </app:TextureAssociation>
                            </app:textureParameterization>
                        </app:ParameterizedTexture>
                    </app:surfaceData>
                    <app:surfaceData>
                        <app:ParameterizedTexture gml:id="UUID_313366b3-db05-47b0-b56b-b26326b1cea1">
                            <app:imageURI>appearance/tex5284720.jpg</app:imageURI>
                            <app:mimeType>image/jpeg</app:mimeType>
                            <app:textureType>unknown</app:textureType>
                            <app:wrapMode>wrap</app:wrapMode>
                            <app:borderColor>1.0 1.0 1.0 1.0</app:borderColor>
                            <app:textureParameterization>
                                <app:TextureAssociation>
                                    <app:uri>#GEOM_6946741</app:uri>
                                    <app:textureParameterization>
                                        <app:TexCoordList>
                                            <app:textureCoordinates>0.002269 0.009191 0.150061 4.63E-4 0.999366 0.99456 0.850859 0.999679 0.002269 0.009191</app:textureCoordinates>
                                            <app:ring>#GEOM_6946741_0_</app:ring>
                                        </app:TexCoordList>
                                    </app:textureParameterization>
                                </app:TextureAssociation>
                            </app:textureParameterization>
                        </app:ParameterizedTexture>
                    </app:surfaceData>
                    <app:surfaceData>
                        <app:ParameterizedTexture gml:id="UUID_5c5dea97-3af0-4702-b74e-fba9a11398f3">
                            <app:imageURI>appearance/tex5284723.jpg</app:imageURI>
                            <app:mimeType>image/jpeg</app:mimeType>
                            <app:textureType>unknown</app:textureType>
                            <app:wrapMode>wrap</app:wrapMode>
                            <app:borderColor>1.0 1.0 1.0 1.0</app:borderColor>
                            <app:textureParameterization>
                                <app:TextureAssociation>
                                    <app:uri>#GEOM_6946742</app:uri>
                                    <app:textureParameterization>
                                        <app:TexCoordList>
                                            <app:textureCoordinates>0.973985 0.004546 0.993854 0.442233 0.017342 0.993678 8.68E-4 0.555611 0.973985 0.004546</app:textureCoordinates>
                                            <app:ring>#GEOM_6946742_0_</app:ring>
                                        </app:TexCoordList>
                                    </app:textureParameterization>
                                </app:TextureAssociation>
                            </app:textureParameterization>
                        </app:ParameterizedTexture>
                    </app:surfaceData>
                    <app:surfaceData>
                        <app:ParameterizedTexture gml:id="UUID_b7886ad7-9a94-4942-b2d6-be0cf00b0e6c">
                            <app:imageURI>appearance/tex5284728.jpg</app:imageURI>
                            <app:mimeType>image/jpeg</app:mimeType>
                            <app:textureType>unknown</app:textureType>
                            <app:wrapMode>wrap</app:wrapMode>
                            <app:borderColor>1.0 1.0 1.0 1.0</app:borderColor>
                            <app:textureParameterization>
                                <app:TextureAssociation>
                                    <app:uri>#GEOM_6946740</app:uri>
                                    <app:textureParameterization>
                                        <app:TexCoordList>
                                            <app:textureCoordinates>4.39E-4 0.999365 0.03404 0.579493 0.993504 0.001988 0.956712 0.422333 4.39E-4 0.999365</app:textureCoordinates>
                                            <app:ring>#GEOM_6946740_0_</app:ring>
                                        </app:TexCoordList>
                                    </app:textureParameterization>
                                </app:TextureAssociation>
                            </app:textureParameterization>
                        </app:ParameterizedTexture>
                    </app:surfaceData>
                    <app:surfaceData>
                        <app:X3DMaterial gml:id="UUID_94aaa1d4-b227-436e-abc6-04bb6588b8e1">
                            <gml:name>Eignung Photovoltaik_EIG_KL_ST_1</gml:name>
                            <app:ambientIntensity>0.2</app:ambientIntensity>
                            <app:diffuseColor>0.83921569 0.30588235 0.21176471</app:diffuseColor>
                            <app:emissiveColor>0.0 0.0 0.0</app:emissiveColor>
                            <app:specularColor>0.0 0.0 0.0</app:specularColor>
                            <app:shininess>0.0</app:shininess>
                            <app:transparency>0.0</app:transparency>
                            <app:target>#UUID_32dfd94a-14ee-466a-b680-b64ccd787c6e</app:target>
                        </app:X3DMaterial>
                    </app:surfaceData>
                </app:Appearance>
            </appearance>
            <appearance>
                <app:Appearance gml:id="UUID_daa240c8-4c4e-4425-ab96-6c435736791f">
                    <app:theme>Eignung Photovoltaik</app:theme>
                    <app:surfaceData>
                        <app:X3DMaterial gml:id="UUID_4db19743-17a2-4b3c-afb5-65914340081e">
                            <gml:name>Eignung Photovoltaik_EIG_KL_PV_3</gml:name>
                            <app:ambientIntensity>0.2</app:ambientIntensity>
                            <app:diffuseColor>0.83921569 0.30588235 0.21176471</app:diffuseColor>
                            <app:emissiveColor>0.0 0.0 0.0</app:emissiveColor>
                            <app:specularColor>0.0 0.0 0.0</app:specularColor>
                            <app:shininess>0.0</app:shininess>
                            <app:transparency>0.0</app:transparency>
                            <app:target>#UUID_32dfd94a-14ee-466a-b680-b64ccd787c6e</app:target>
                        </app:X3DMaterial>
                    </app:surfaceData>
                    <app:surfaceData xlink:href="#UUID_60ccf25e-f370-4df4-a1d0-62414138f95a"/>
                    <app:surfaceData xlink:href="#UUID_5c5dea97-3af0-4702-b74e-fba9a11398f3"/>
                    <app:surfaceData xlink:href="#UUID_b7886ad7-9a94-4942-b2d6-be0cf00b0e6c"/>
                    <app:surfaceData xlink:href="#UUID_313366b3-db05-47b0-b56b-b26326b1cea1"/>
                </app:Appearance>
            </appearance>
            <appearance>
                <app:Appearance gml:id="UUID_a22992f2-0141-4ad4-8530-e03254737d70">
                    <app:theme>rgbTexture</app:theme>
                    <app:surfaceData>
                        <app:ParameterizedTexture gml:id="UUID_2aee9ac9-ab95-4e12-b424-02b7bc1eb732">
                            <app:imageURI>appearance/tex5284745.jpg</app:imageURI>
                            <app:mimeType>image/jpeg</app:mimeType>
                            <app:textureType>unknown</app:textureType>
                            <app:wrapMode>wrap</app:wrapMode>
                            <app:borderColor>1.0 1.0 1.0 1.0</app:borderColor>
                            <app:textureParameterization>
                                <app:TextureAssociation>
                                    <app:uri>#GEOM_6946745</app:uri>
                                    <app:textureParameterization>
                                        <app:TexCoordList>
                                            <app:textureCoordinates>0.144638 0.997614 9.37E-4 0.702191 0.854959 8.26E-4 0.998682 0.296271 0.144638 0.997614</app:textureCoordinates>
                                            <app:ring>#GEOM_6946745_0_</app:ring>
                                        </app:TexCoordList>
                                    </app:textureParameterization>
                                </app:TextureAssociation>
                            </app:textureParameterization>
                        </app:ParameterizedTexture>
                    </app:surfaceData>
                    <app:surfaceData xlink:href="#UUID_60ccf25e-f370-4df4-a1d0-62414138f95a"/>
                    <app:surfaceData xlink:href="#UUID_b7886ad7-9a94-4942-b2d6-be0cf00b0e6c"/>
                    <app:surfaceData xlink:href="#UUID_5c5dea97-3af0-4702-b74e-fba9a11398f3"/>
                    <app:surfaceData xlink:href="#UUID_313366b3-db05-47b0-b56b-b26326b1cea1"/>
                </app:Appearance>
            </appearance>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>GE_LoD2_zOffset</gen:name>
                    <gen:value>Auto|1.5004691629395026|28.02.2015 18:40:37</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:IntAttribute>
                    <gen:name>EIG_KL_ST</gen:name>
                    <gen:value>1</gen:value>
                </gen:IntAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:IntAttribute>
                    <gen:name>EIG_KL_PV</gen:name>
                    <gen:value>3</gen:value>
                </gen:IntAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>FOLIE</gen:name>
                    <gen:value>011</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:DoubleAttribute>
                    <gen:name>H_First_Min</gen:name>
                    <gen:value>37.13551</gen:value>
                </gen:DoubleAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:DoubleAttribute>
                    <gen:name>H_First_Max</gen:name>
                    <gen:value>37.13551</gen:value>
                </gen:DoubleAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:DoubleAttribute>
                    <gen:name>H_Trauf_Min</gen:name>
                    <gen:value>37.13551</gen:value>
                </gen:DoubleAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:DoubleAttribute>
                    <gen:name>H_Trauf_Max</gen:name>
                    <gen:value>37.13551</gen:value>
                </gen:DoubleAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:IntAttribute>
                    <gen:name>TexVersion</gen:name>
                    <gen:value>1</gen:value>
                </gen:IntAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>Kachel</gen:name>
                    <gen:value>2100021000</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>LAND</gen:name>
                    <gen:value>11</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>RBEZ</gen:name>
                    <gen:value>0</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>KREIS</gen:name>
                    <gen:value>00</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>GMDE</gen:name>
                    <gen:value>001</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>STR</gen:name>
                    <gen:value>01997</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>HNR</gen:name>
                    <gen:value>18</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:StringAttribute>
                    <gen:name>LFD</gen:name>
                    <gen:value>001</gen:value>
                </gen:StringAttribute>
            </genericAttribute>
            <genericAttribute>
                <gen:IntAttribute>
                    <gen:name>ANZ_LOC</gen:name>
                    <gen:value>1</gen:value>
                </gen:IntAttribute>
            </genericAttribute>
            <boundary>
                <con:GroundSurface>
                    <gml:boundedBy>
                        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG:6.12:25833,crs:EPSG:6.12:5783" srsDimension="3">
                            <gml:lowerCorner>388662.065952828 5818794.94363763 33.0499992370605</gml:lowerCorner>
                            <gml:upperCorner>388694.554505901 5818814.54557574 33.0499992370605</gml:upperCorner>
                        </gml:Envelope>
                    </gml:boundedBy>
                    <creationDate>2015-04-22T00:00:00</creationDate>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="UUID_52661b3e-6911-47f3-a3ab-4fe9e6695c4a">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946738">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946738_0_">
                                            <gml:posList srsDimension="3">388662.279883488 5818806.80170332 33.0499992370605 388665.429453485 5818814.48846886 33.0499992370605 388694.340575076 5818802.6875095 33.0499992370605 388691.191005534 5818795.00074437 33.0499992370605 388662.279883488 5818806.80170332 33.0499992370605</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:GroundSurface>
            </boundary>
            <boundary>
                <con:WallSurface>
                    <gml:boundedBy>
                        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG:6.12:25833,crs:EPSG:6.12:5783" srsDimension="3">
                            <gml:lowerCorner>388662.065952828 5818794.94363763 33.0499992370605</gml:lowerCorner>
                            <gml:upperCorner>388694.554592955 5818814.54570483 37.1355108373305</gml:upperCorner>
                        </gml:Envelope>
                    </gml:boundedBy>
                    <creationDate>2015-04-22T00:00:00</creationDate>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="UUID_db9cea97-6308-4877-8c14-011adf1dfc6c">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946743">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946743_0_">
                                            <gml:posList srsDimension="3">388691.191005534 5818795.00074437 33.0499992370605 388691.191092587 5818795.00087346 37.1355108373305 388662.279970539 5818806.80183241 37.1355108373305 388662.279883488 5818806.80170332 33.0499992370605 388691.191005534 5818795.00074437 33.0499992370605</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946742">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946742_0_">
                                            <gml:posList srsDimension="3">388662.279883488 5818806.80170332 33.0499992370605 388662.279970539 5818806.80183241 37.1355108373305 388665.429540537 5818814.48859795 37.1355108373305 388665.429453485 5818814.48846886 33.0499992370605 388662.279883488 5818806.80170332 33.0499992370605</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946741">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946741_0_">
                                            <gml:posList srsDimension="3">388665.429453485 5818814.48846886 33.0499992370605 388665.429540537 5818814.48859795 37.1355108373305 388694.340662129 5818802.68763858 37.1355108373305 388694.340575076 5818802.6875095 33.0499992370605 388665.429453485 5818814.48846886 33.0499992370605</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946740">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946740_0_">
                                            <gml:posList srsDimension="3">388694.340575076 5818802.6875095 33.0499992370605 388694.340662129 5818802.68763858 37.1355108373305 388691.191092587 5818795.00087346 37.1355108373305 388691.191005534 5818795.00074437 33.0499992370605 388694.340575076 5818802.6875095 33.0499992370605</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:WallSurface>
            </boundary>
            <boundary>
                <con:RoofSurface>
                    <gml:boundedBy>
                        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG:6.12:25833,crs:EPSG:6.12:5783" srsDimension="3">
                            <gml:lowerCorner>388662.06603988 5818794.94376672 37.1355108373305</gml:lowerCorner>
                            <gml:upperCorner>388694.554592955 5818814.54570483 37.1355108373305</gml:upperCorner>
                        </gml:Envelope>
                    </gml:boundedBy>
                    <creationDate>2015-04-22T00:00:00</creationDate>
                    <lod2MultiSurface>
                        <gml:MultiSurface gml:id="UUID_32dfd94a-14ee-466a-b680-b64ccd787c6e">
                            <gml:surfaceMember>
                                <gml:Polygon gml:id="GEOM_6946745">
                                    <gml:exterior>
                                        <gml:LinearRing gml:id="GEOM_6946745_0_">
                                            <gml:posList srsDimension="3">388691.191092587 5818795.00087346 37.1355108373305 388694.340662129 5818802.68763858 37.1355108373305 388665.429540537 5818814.48859795 37.1355108373305 388662.279970539 5818806.80183241 37.1355108373305 388691.191092587 5818795.00087346 37.1355108373305</gml:posList>
                                        </gml:LinearRing>
                                    </gml:exterior>
                                </gml:Polygon>
                            </gml:surfaceMember>
                        </gml:MultiSurface>
                    </lod2MultiSurface>
                </con:RoofSurface>
            </boundary>
            <con:height>
                <con:Height>
                    <con:highReference>highestRoofEdge</con:highReference>
                    <con:lowReference>lowestGroundPoint</con:lowReference>
                    <con:status>measured</con:status>
                    <con:value uom="urn:ogc:def:uom:UCUM::m">4.08551</con:value>
                </con:Height>
            </con:height>
            <bldg:function>1179</bldg:function>
            <bldg:address>
                <Address gml:id="ID_148325">
                    <xalAddress>
                        <xAL:AddressDetails>
                            <xAL:Country>
                                <xAL:Locality Type="Town">
                                    <xAL:LocalityName>Berlin</xAL:LocalityName>
                                    <xAL:Thoroughfare Type="Street">
                                        <xAL:ThoroughfareNumber>18</xAL:ThoroughfareNumber>
                                        <xAL:ThoroughfareName>Hildebrandstr.</xAL:ThoroughfareName>
                                    </xAL:Thoroughfare>
                                </xAL:Locality>
                            </xAL:Country>
                        </xAL:AddressDetails>
                    </xalAddress>
                </Address>
            </bldg:address>
        </bldg:Building>
    </cityObjectMember>
</CityModel>
